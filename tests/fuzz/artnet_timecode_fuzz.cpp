// Fuzz harness: one UDP datagram through the ArtTimeCode parser (parseArtTimeCode).
#include "fuzz/harness.h"
#include "shows/dmx/artnet_timecode.h"

namespace haze::fuzz {

bool acceptArtTimeCode(const uint8_t* data, size_t size) {
  const ArtTimeCodeParse parse = parseArtTimeCode(std::span<const uint8_t>(data, size));
  if (parse.ok()) (void)parse.packet.time.str();
  return parse.ok();
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptArtTimeCode)
