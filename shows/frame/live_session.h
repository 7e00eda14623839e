// One live session: what `haze live` and the GUI's live mode both drive. It takes DMX from a
// console (Art-Net, sACN: merged and decoded by LiveReceiver), OSC remote commands, ArtTimeCode
// and MIDI Time Code, plays the chosen cue list on LivePlayback with the console's fixtures laid
// over it, and keeps the commanded stage and (optionally) where the heads really are, moving at
// the fixtures' speeds (docs/movement.md).
//
// The session has two halves. Its core takes inputs as values, with time passed in (seconds on
// a monotonic clock): osc(), timecode(), update(); tests drive it without sockets. listen()
// opens the sockets (DMX, OSC, the ALSA sequencer for MTC) and pass() reads them once and feeds
// the core on the steady clock. Everything worth a line to the operator ("OSC /haze/go from
// ...: cue 2", a universe that receives DMX but drives nothing) goes to the log callback.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "shows/dmx/dmx_reach.h"
#include "shows/dmx/midi_timecode.h"
#include "shows/dmx/udp_receiver.h"
#include "shows/frame/live_playback.h"
#include "shows/movement.h"

namespace haze {

class MidiSeqInput;

// Text from the network for a log line: bytes outside printable ASCII shown as '?'.
std::string printable(const std::string& s);

struct LiveSessionConfig {
  const CueList* cueList = nullptr;  // the list OSC and timecode play (null: the show has none)
  bool playback = false;             // OSC, timecode or MTC: the cue list plays under the DMX
  bool followHeads = true;           // track the heads' travel (the GUI follows them itself)
};

// The inputs listen() opens. DMX always; the others when asked.
struct LiveInputs {
  LiveOptions dmx;
  int oscPort = -1;  // -1: no OSC; 0: a free port
  bool artTimecode = false;
  bool mtc = false;
  std::string mtcFrom;  // "" = wait for a sender to connect
};

struct LiveControlStats {
  uint64_t oscCommands = 0, oscRefused = 0, timecodeFired = 0;
  double longestPassMs = 0.0;  // the longest pass() so far
};

class LiveSession {
 public:
  using Log = std::function<void(const std::string&)>;

  // show and profiles (and config.cueList) must outlive the session. log may be empty.
  LiveSession(const Show& show, const ProfileSet& profiles, const LiveSessionConfig& config, Log log);
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  // ---- the core: inputs as values, time passed in ----
  // An OSC datagram from `from` ("a.b.c.d:port"): parsed, applied to the playback, logged; returns
  // the reply to send back.
  std::vector<uint8_t> osc(std::span<const uint8_t> datagram, const std::string& from, double nowS);
  // A timecode reading from `source` ("timecode": ArtTimeCode, "MTC") at fps: fires what it reaches.
  void timecode(const Timecode& time, double fps, const char* source, double nowS);
  // The stage at nowS from the console's DMX (dmxFixtures: the fixtures it drives) and the
  // playback. The heads start where the first DMX puts them (dmxArrived), as a rig switched on
  // at the console's look; each DMX value is a step from the pass that brought it.
  void update(double nowS, const StageState& dmx, const std::set<int>& dmxFixtures, bool dmxArrived);
  // The last command, and the heads moved towards it; the last is finished by finish().
  const StageState& commanded() const { return commanded_; }
  const StageState& moved() const { return moved_; }

  // ---- with sockets ----
  // Opens the inputs, logging each address; the Error reads as one line.
  Status listen(const LiveInputs& inputs);
  // Reads what arrived (waiting up to waitMs for DMX), then update() on the steady clock.
  // Returns the commanded stage.
  const StageState& pass(int waitMs);
  // The last reading: DMX polled once more, the command and the heads at this moment.
  void finish();
  // How long a pass should wait for DMX: short while OSC and timecode need reading on time.
  int maxWaitMs() const { return config_.playback ? 5 : 100; }
  static double clockS();  // the steady clock, in seconds

  // ---- what it knows ----
  const std::vector<UniverseReach>& reach() const { return reach_; }
  bool dmxArrived() const { return receiver_ && receiver_->stats().good > 0; }
  LiveReceiver& receiver() { return *receiver_; }
  const LiveReceiver& receiver() const { return *receiver_; }
  int oscPort() const;  // 0 when there is no OSC socket
  bool mtcOpen() const { return mtcIn_ != nullptr; }
  const MtcStats& mtcStats() const { return mtcDecoder_.stats(); }
  const LiveControlStats& stats() const { return stats_; }
  const std::string& camera() const;  // the camera /haze/camera chose ("" until then)
  const std::map<int, CueValues>& programmer() const;  // what OSC fixture messages set
  double secondsSinceStart() const { return clockS() - start_; }

 private:
  void say(const std::string& line) const {
    if (log_) log_(line);
  }
  void warnIdleUniverses();
  void pumpTimecodes();

  const Show& show_;
  const ProfileSet& profiles_;
  LiveSessionConfig config_;
  Log log_;
  std::optional<LivePlayback> playback_;
  std::vector<UniverseReach> reach_;
  std::set<int> drivingUniverses_, warnedUniverses_;
  uint64_t goodSeen_ = 0, unwatchedSeen_ = 0;
  MovementFollower heads_;
  StageState commanded_, moved_;
  bool seeded_ = false;
  double start_ = 0.0;  // the heads' time 0
  LiveControlStats stats_;

  std::unique_ptr<LiveReceiver> receiver_;
  std::unique_ptr<OscSocket> osc_;
  std::unique_ptr<MidiSeqInput> mtcIn_;
  MtcDecoder mtcDecoder_;
  bool artTimecode_ = false;
};

}  // namespace haze
