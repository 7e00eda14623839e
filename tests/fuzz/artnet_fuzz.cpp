// Fuzz harness: one UDP datagram through the Art-Net parser (parseArtDmx).
#include "fuzz/harness.h"
#include "shows/dmx/artnet.h"

namespace haze::fuzz {

bool acceptArtNet(const uint8_t* data, size_t size) {
  const ArtDmxParse parse = parseArtDmx(std::span<const uint8_t>(data, size));
  if (parse.status != ArtNetStatus::Ok) {
    (void)artNetError(parse);
    return false;
  }
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptArtNet)
