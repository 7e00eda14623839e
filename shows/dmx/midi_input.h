// MIDI in from the ALSA sequencer (Debian's libasound2) for MIDI Time Code: a port of haze's own
// ("haze" client, "MTC in" port) that other programs or hardware connect to (aconnect), or that
// connects itself to a given sender (`--mtc-from CLIENT:PORT`). Quarter-frame and sysex events
// are handed on as the MIDI bytes they came from (F1 0n; F0 ... F7), for MtcDecoder. Non-blocking;
// where the machine has no sequencer (/dev/snd/seq absent) open() says so.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include "fixtures/core/result.h"

typedef struct _snd_seq snd_seq_t;

namespace haze {

class MidiSeqInput {
 public:
  // from: "" = wait for connections; else an ALSA address ("20:0", "Virtual Raw MIDI 1-0:0").
  static Result<std::unique_ptr<MidiSeqInput>> open(const std::string& from);
  ~MidiSeqInput();
  MidiSeqInput(const MidiSeqInput&) = delete;
  MidiSeqInput& operator=(const MidiSeqInput&) = delete;

  // Hands each pending quarter-frame or sysex event's bytes to `handle` (at most maxEvents, no
  // waiting); returns how many events were read.
  int pump(const std::function<void(std::span<const uint8_t>)>& handle, int maxEvents = 4096);
  std::string address() const;  // "128:0": where senders connect

 private:
  MidiSeqInput() = default;
  snd_seq_t* seq_ = nullptr;
  int client_ = -1, port_ = -1;
};

}  // namespace haze
