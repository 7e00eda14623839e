// ALSA sequencer input for MIDI Time Code (see midi_input.h).
#include "shows/dmx/midi_input.h"

#include <alsa/asoundlib.h>

#include <cerrno>
#include <unistd.h>

namespace haze {

namespace {
// alsa-lib prints its own errors to stderr; haze reports them in one line of its own instead.
void quiet(const char*, int, const char*, int, const char*, ...) {}
}  // namespace

Result<std::unique_ptr<MidiSeqInput>> MidiSeqInput::open(const std::string& from) {
  snd_lib_error_set_handler(quiet);
  std::unique_ptr<MidiSeqInput> in(new MidiSeqInput());
  const int rc = snd_seq_open(&in->seq_, "default", SND_SEQ_OPEN_INPUT, SND_SEQ_NONBLOCK);
  if (rc < 0) {
    in->seq_ = nullptr;
    const bool absent = access("/dev/snd/seq", F_OK) != 0;
    return Error{"ALSA sequencer", "", std::string("cannot open it: ") + snd_strerror(rc) +
                                           (absent ? " (/dev/snd/seq is absent: the snd-seq kernel module is not loaded)" : "")};
  }
  snd_seq_set_client_name(in->seq_, "haze");
  in->port_ = snd_seq_create_simple_port(in->seq_, "MTC in", SND_SEQ_PORT_CAP_WRITE | SND_SEQ_PORT_CAP_SUBS_WRITE,
                                         SND_SEQ_PORT_TYPE_MIDI_GENERIC | SND_SEQ_PORT_TYPE_APPLICATION);
  if (in->port_ < 0) return Error{"ALSA sequencer", "", std::string("cannot create a port: ") + snd_strerror(in->port_)};
  in->client_ = snd_seq_client_id(in->seq_);
  if (!from.empty()) {
    snd_seq_addr_t addr;
    if (int e = snd_seq_parse_address(in->seq_, &addr, from.c_str()); e < 0)
      return Error{"ALSA sequencer", from, std::string("no such MIDI port: ") + snd_strerror(e)};
    if (int e = snd_seq_connect_from(in->seq_, in->port_, addr.client, addr.port); e < 0)
      return Error{"ALSA sequencer", from, std::string("cannot connect from it: ") + snd_strerror(e)};
  }
  return in;
}

MidiSeqInput::~MidiSeqInput() {
  if (seq_) snd_seq_close(seq_);
}

std::string MidiSeqInput::address() const { return std::to_string(client_) + ":" + std::to_string(port_); }

int MidiSeqInput::pump(const std::function<void(std::span<const uint8_t>)>& handle, int maxEvents) {
  int n = 0;
  for (; n < maxEvents; ++n) {
    snd_seq_event_t* ev = nullptr;
    const int rc = snd_seq_event_input(seq_, &ev);
    if (rc == -EAGAIN) break;
    if (rc == -ENOSPC) continue;  // the input queue overran: events were lost, go on with what comes next
    if (rc < 0 || !ev) break;
    if (ev->type == SND_SEQ_EVENT_QFRAME) {
      const uint8_t bytes[2] = {0xF1, static_cast<uint8_t>(ev->data.control.value & 0x7F)};
      handle(bytes);
    } else if (ev->type == SND_SEQ_EVENT_SYSEX && ev->data.ext.ptr) {
      handle(std::span<const uint8_t>(static_cast<const uint8_t*>(ev->data.ext.ptr), ev->data.ext.len));
    }
  }
  return n;
}

}  // namespace haze
