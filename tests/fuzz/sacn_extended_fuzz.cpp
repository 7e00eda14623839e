// Fuzz harness: one UDP datagram through the sACN extended-packet parser (parseSacnExtended:
// E1.31 synchronization and universe discovery).
#include "fuzz/harness.h"
#include "shows/dmx/sacn.h"

namespace haze::fuzz {

bool acceptSacnExtended(const uint8_t* data, size_t size) {
  const SacnExtendedParse parse = parseSacnExtended(std::span<const uint8_t>(data, size));
  if (!parse.ok()) {
    (void)sacnError(parse.status, parse.byte);
    return false;
  }
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptSacnExtended)
