// The live session (see live_session.h): the inputs of `haze live` and the GUI's live mode fed
// into one cue engine and one stage.
#include "shows/frame/live_session.h"

#include <algorithm>
#include <chrono>

#include "shows/dmx/midi_input.h"
#include "shows/dmx/osc_command.h"

namespace haze {

namespace {
// Refusals are logged up to this many; a flood of bad messages is then only counted.
constexpr uint64_t kLoggedRefusals = 20;
}  // namespace

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
  return out;
}

LiveSession::LiveSession(const Show& show, const ProfileSet& profiles, const LiveSessionConfig& config, Log log)
    : show_(show), profiles_(profiles), config_(config), log_(std::move(log)), reach_(dmxReach(show, profiles)), heads_(show, profiles) {
  if (config_.playback) playback_.emplace(show, profiles, config_.cueList);
  for (const UniverseReach& u : reach_)
    if (!u.driven.empty()) drivingUniverses_.insert(u.universe);
  commanded_ = moved_ = playback_ ? playback_->stage(clockS(), {}, {}) : StageState{};
  heads_.reset(commanded_, 0.0);
  start_ = clockS();
}

LiveSession::~LiveSession() = default;

double LiveSession::clockS() { return LiveReceiver::nowS(); }

std::vector<uint8_t> LiveSession::osc(std::span<const uint8_t> datagram, const std::string& from, double nowS) {
  OscParse p = parseOscCommand(datagram);
  if (p.ok) {
    Result<std::string> done = playback_ ? playback_->apply(p.command, nowS)
                                         : Result<std::string>(Error{"", "", "no cue engine in this session"});
    if (done) {
      ++stats_.oscCommands;
      say("OSC " + printable(p.address) + " from " + from + ": " + *done);
    } else {
      p.ok = false;
      p.error = done.error().str();
    }
  }
  if (!p.ok && ++stats_.oscRefused <= kLoggedRefusals)
    say("OSC from " + from + " refused: " + printable(p.error) +
        (stats_.oscRefused == kLoggedRefusals ? " (further refusals are only counted)" : ""));
  return oscReply(p);
}

void LiveSession::timecode(const Timecode& time, double fps, const char* source, double nowS) {
  if (!playback_) return;
  const std::string what = playback_->timecode(time, fps, nowS);
  if (what.empty()) return;
  ++stats_.timecodeFired;
  say(std::string(source) + " " + time.str() + ": " + what);
}

void LiveSession::update(double nowS, const StageState& dmx, const std::set<int>& dmxFixtures, bool dmxArrived) {
  const double t = nowS - start_;
  // The command before this pass holds until now: a DMX value is a step at the pass that brought it.
  if (config_.followHeads) moved_ = heads_.advance(commanded_, t, false);
  commanded_ = playback_ ? playback_->stage(nowS, dmx, dmxFixtures) : dmx;
  if (!seeded_ && dmxArrived) {
    heads_.reset(commanded_, t);
    seeded_ = true;
  }
  if (!config_.followHeads) moved_ = commanded_;
}

Status LiveSession::listen(const LiveInputs& inputs) {
  auto live = LiveReceiver::open(show_, profiles_, inputs.dmx);
  if (!live) return live.error();
  receiver_ = std::move(*live);
  const std::string& bind = inputs.dmx.udp.bindAddress;
  if (const int port = receiver_->udp().artNetPort())
    say("Art-Net on " + bind + ":" + std::to_string(port) + " (haze universe = Port-Address + 1)");
  if (const int port = receiver_->udp().sacnPort()) say("sACN on " + bind + ":" + std::to_string(port));
  if (inputs.mtc) {
    auto m = MidiSeqInput::open(inputs.mtcFrom);
    if (!m) return Error{"", "", "--mtc: " + m.error().str()};
    mtcIn_ = std::move(*m);
    say("MTC on " + mtcIn_->address() + " (ALSA sequencer client \"haze\", port \"MTC in\"" +
        (inputs.mtcFrom.empty() ? "" : "; connected from " + inputs.mtcFrom) + ")");
  }
  if (inputs.oscPort >= 0) {
    auto o = OscSocket::open(bind, inputs.oscPort);
    if (!o) return o.error();
    osc_ = std::move(*o);
    say("OSC on " + bind + ":" + std::to_string(osc_->port()));
  }
  for (const std::string& note : receiver_->udp().notes()) say(note);
  artTimecode_ = inputs.artTimecode;
  // The heads start on the stage as it is before any DMX; time 0 is now.
  commanded_ = moved_ = playback_ ? playback_->stage(clockS(), receiver_->state(), receiver_->input().dmxFixtures())
                                  : receiver_->state();
  heads_.reset(commanded_, 0.0);
  start_ = clockS();
  return Ok{};
}

int LiveSession::oscPort() const { return osc_ ? osc_->port() : 0; }

void LiveSession::pumpTimecodes() {
  if (mtcIn_) {
    mtcIn_->pump([&](std::span<const uint8_t> bytes) {
      for (const MtcReading& r : mtcDecoder_.feed(bytes)) timecode(r.time, r.fps(), "MTC", clockS());
    });
  }
  if (artTimecode_)
    for (const ArtTimeCodePacket& tc : receiver_->input().takeTimecodes()) timecode(tc.time, tc.fps(), "timecode", clockS());
}

const StageState& LiveSession::pass(int waitMs) {
  const double passStart = clockS();
  receiver_->poll(waitMs);
  if (osc_)
    osc_->pump([&](std::span<const uint8_t> datagram, const std::string& from) { return osc(datagram, from, clockS()); });
  pumpTimecodes();
  update(clockS(), receiver_->state(), receiver_->input().dmxFixtures(), dmxArrived());
  warnIdleUniverses();
  // Whole passes: a pass that found nothing waited waitMs; one that found a flood did its work.
  stats_.longestPassMs = std::max(stats_.longestPassMs, (clockS() - passStart) * 1000.0);
  return commanded_;
}

void LiveSession::finish() {
  const StageState& dmx = receiver_->poll(0);
  const double now = clockS();
  commanded_ = playback_ ? playback_->stage(now, dmx, receiver_->input().dmxFixtures()) : dmx;
  moved_ = config_.followHeads ? heads_.advance(commanded_, now - start_, false) : commanded_;
}

// Once per universe: DMX arrives for it, and it drives nothing.
void LiveSession::warnIdleUniverses() {
  const DmxInputStats& s = receiver_->stats();
  if (s.good == goodSeen_ && s.unwatched == unwatchedSeen_) return;
  goodSeen_ = s.good;
  unwatchedSeen_ = s.unwatched;
  for (int u : s.unwatchedUniverses)
    if (warnedUniverses_.insert(u).second)
      say("warning: universe " + std::to_string(u) + " receives DMX, but no fixture of the show is patched on it");
  for (const DmxSourceInfo& src : receiver_->sources())
    if (!drivingUniverses_.count(src.universe) && warnedUniverses_.insert(src.universe).second)
      say("warning: universe " + std::to_string(src.universe) +
          " receives DMX, but it drives no fixture (see the lines above for why)");
}

const std::string& LiveSession::camera() const {
  static const std::string kNone;
  return playback_ ? playback_->camera() : kNone;
}

const std::map<int, CueValues>& LiveSession::programmer() const {
  static const std::map<int, CueValues> kNone;
  return playback_ ? playback_->programmer() : kNone;
}

}  // namespace haze
