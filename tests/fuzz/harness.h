// The fuzz harness functions, one per file parser: each feeds arbitrary bytes to one in-memory
// entry point. libFuzzer calls them through LLVMFuzzerTestOneInput (HAZE_FUZZ=ON, clang), and
// the unit suite unit_fuzz_replay calls them on the corpus in every ordinary build.
#pragma once

#include <cstddef>
#include <cstdint>

#include "fixtures/photometry.h"

namespace haze::fuzz {

// An accepted distribution must also be safe to use: lookups walk the grid and its symmetry.
inline void useDistribution(const Distribution& d) {
  for (float t : {0.0f, 0.3f, 1.5f, 3.1f})
    for (float p : {0.0f, 1.0f, 4.0f, 6.2f}) (void)d.intensityCd(t, p);
  (void)d.peakCd();
  (void)d.maxThetaRad();
}

// Each returns true when the parser accepted the input (the replay checks that valid seeds
// are accepted and broken ones refused); false is a clean refusal. Nothing may crash or throw.
bool acceptIes(const uint8_t* data, size_t size);
bool acceptLdt(const uint8_t* data, size_t size);
bool acceptProfileJson(const uint8_t* data, size_t size);
bool acceptShow(const uint8_t* data, size_t size);
bool acceptVenue(const uint8_t* data, size_t size);
bool acceptGdtf(const uint8_t* data, size_t size);
bool acceptGdtfXml(const uint8_t* data, size_t size);  // description.xml alone, zipped here
bool acceptMvr(const uint8_t* data, size_t size);
bool acceptArtNet(const uint8_t* data, size_t size);
bool acceptSacn(const uint8_t* data, size_t size);
bool acceptSacnExtended(const uint8_t* data, size_t size);
bool acceptArtTimeCode(const uint8_t* data, size_t size);
bool acceptOsc(const uint8_t* data, size_t size);
bool acceptMidiTimecode(const uint8_t* data, size_t size);
bool acceptMesh(const uint8_t* data, size_t size);  // .3ds / .glb / .gltf by the first bytes
bool acceptQxf(const uint8_t* data, size_t size);   // a QLC+ fixture definition
bool acceptSvgGobo(const uint8_t* data, size_t size);  // an SVG gobo image, rasterised
bool acceptXchange(const uint8_t* data, size_t size);  // an MVR-xchange TCP stream, decoded and answered

}  // namespace haze::fuzz

// In a libFuzzer build each harness file is its own program; elsewhere this expands to nothing.
#ifdef HAZE_LIBFUZZER
#define HAZE_FUZZ_ENTRY(fn)                                                      \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {      \
    (void)haze::fuzz::fn(data, size);                                            \
    return 0;                                                                    \
  }
#else
#define HAZE_FUZZ_ENTRY(fn)
#endif
