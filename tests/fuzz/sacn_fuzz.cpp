// Fuzz harness: one UDP datagram through the sACN (E1.31) parser (parseSacn).
#include "fuzz/harness.h"
#include "shows/dmx/sacn.h"

namespace haze::fuzz {

bool acceptSacn(const uint8_t* data, size_t size) {
  const SacnParse parse = parseSacn(std::span<const uint8_t>(data, size));
  if (!parse.ok()) {
    (void)sacnError(parse);
    return false;
  }
  return true;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptSacn)
