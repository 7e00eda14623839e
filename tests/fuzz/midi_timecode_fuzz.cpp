// Fuzz harness: a MIDI byte stream through the MIDI Time Code decoder (quarter frames and Full
// Frame sysex). Accepted when it gives at least one reading.
#include "fuzz/harness.h"
#include "shows/dmx/midi_timecode.h"

namespace haze::fuzz {

bool acceptMidiTimecode(const uint8_t* data, size_t size) {
  MtcDecoder decoder;
  return !decoder.feed(std::span<const uint8_t>(data, size)).empty();
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptMidiTimecode)
