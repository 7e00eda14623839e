// Fuzz harness: one UDP datagram through the OSC remote-control decoder (parseOscCommand, on
// liblo's deserialiser) and the reply it would get.
#include "fuzz/harness.h"
#include "shows/dmx/osc_command.h"

namespace haze::fuzz {

bool acceptOsc(const uint8_t* data, size_t size) {
  const OscParse parse = parseOscCommand(std::span<const uint8_t>(data, size));
  (void)oscReply(parse);
  return parse.ok;
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptOsc)
