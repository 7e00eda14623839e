// haze live SHOW [--artnet] [--sacn] [--bind ADDR] [--duration S] [--state-json OUT]
//                [--render OUT.png] [--osc PORT] [--timecode] [--mtc] [--record-cue N]: DMX in from a
// console, headless, optionally with haze's own cue list remote-controlled over OSC or fired by
// ArtTimeCode or MIDI Time Code. Receives for S seconds (or until SIGINT/SIGTERM), then writes the fixtures' final
// states, renders them and/or records them into a cue, and prints what arrived (good packets,
// drops by reason, rate, sources) to stderr.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/render_job.h"
#include "shows/dmx/dmx_reach.h"
#include "shows/frame/live_playback.h"
#include "shows/frame/live_record.h"
#include "shows/frame/state_json.h"
#include "shows/dmx/midi_input.h"
#include "shows/dmx/midi_timecode.h"
#include "shows/dmx/osc_command.h"
#include "app/xchange_station.h"
#include "shows/dmx/udp_receiver.h"
#include "shows/movement.h"
#include "fixtures/core/atomic_file.h"
#include "shows/cue_number.h"
#include "shows/show.h"
#include "shows/show_json.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze live SHOW [--artnet] [--sacn] [--bind ADDR] [--duration S]\n"
    "                 [--state-json OUT.json] [--render OUT.png|OUT.pfm]\n"
    "                 [--artnet-port P] [--sacn-port P] [--multicast] [--on-loss hold|blackout]\n"
    "                 [--no-preview] [--camera NAME] [--width W --height H] [--quality Q]\n"
    "                 [--exposure EV] [--exposure-mode auto|manual]\n"
    "                 [--osc PORT] [--timecode] [--mtc [--mtc-from CLIENT:PORT]] [--cue-list NAME]\n"
    "                 [--record-cue N [--label L]] [--no-sync]\n"
    "                 [--mvr-xchange [--group NAME] [--mvr-xchange-port N] [--mvr-xchange-peer HOST:PORT]...\n"
    "                  [--accept-commits DIR] [--station-name NAME]]\n"
    "Listens for Art-Net (UDP 6454) and sACN E1.31 (UDP 5568); neither flag means both.\n"
    "--bind: the local IPv4 address to listen on (default 127.0.0.1: this machine only).\n"
    "sACN universe N is haze universe N; Art-Net Port-Address P (Net:Sub-Net:Universe) is\n"
    "haze universe P + 1, so Art-Net 0:0:0 drives patch universe 1.\n"
    "sACN multicast (239.255.hi.lo) is joined for the patched universes when --bind is not a\n"
    "loopback address, or with --multicast. Port 0 picks a free port (printed on stderr).\n"
    "--duration 0 (the default) runs until Ctrl-C.\n"
    "--movement real|instant: heads follow DMX and cues at the fixtures' speeds (default) or jump at once.\n"
    "--osc PORT: OSC remote control on --bind:PORT (/haze/go, /haze/back, /haze/cue N,\n"
    "/haze/fixture/ID/ATTRIBUTE V, /haze/clear, /haze/camera NAME; docs/live.md). --timecode: ArtTimeCode fires the\n"
    "cues that have a \"timecode\"; --mtc: MIDI Time Code from the ALSA sequencer does (port \"haze\",\n"
    "or --mtc-from connects to a sender). They play --cue-list (default: the first list); fixtures on a\n"
    "universe with DMX follow the console. --record-cue N: on exit, the commanded stage (where the\n"
    "heads are going, not where they are) is recorded into cue N (tracking: only what differs) and\n"
    "the show saved safely.\n"
    "--mvr-xchange: haze is an MVR-xchange station of --group (default \"Default\"): announced over mDNS when\n"
    "avahi-daemon runs, on --bind:--mvr-xchange-port (0: a free port); --mvr-xchange-peer dials a station\n"
    "directly. Stations get the show as MVR; saving the show file sends them a commit; --accept-commits DIR\n"
    "imports what they commit into new shows in DIR (docs/mvr.md, \"MVR-xchange\").\n";

// Per universe: the fixtures DMX drives, each it cannot (one line, with why), and those whose
// intensity no channel sets (at full: docs/live.md, "What the console drives").
void printReach(const std::vector<UniverseReach>& reach) {
  for (const UniverseReach& u : reach) {
    const size_t patched = u.driven.size() + u.undriven.size();
    std::fprintf(stderr, "haze live: universe %d: drives %zu of %zu patched fixtures%s%s\n", u.universe,
                 u.driven.size(), patched, u.driven.empty() ? "" : ": ", idRanges(u.driven).c_str());
    for (const auto& [id, why] : u.undriven)
      std::fprintf(stderr, "haze live: universe %d: cannot drive fixture %d: %s\n", u.universe, id, why.c_str());
    std::map<std::string, std::vector<int>> atFull;
    for (const auto& [id, why] : u.atFull) atFull[why].push_back(id);
    for (const auto& [why, ids] : atFull)
      std::fprintf(stderr, "haze live: universe %d: fixture%s %s: %s; intensity stays at full whatever DMX sends\n",
                   u.universe, ids.size() == 1 ? "" : "s", idRanges(ids).c_str(), why.c_str());
  }
}

volatile std::sig_atomic_t gStop = 0;
void onSignal(int) { gStop = 1; }

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
  return out;
}

struct ControlStats {
  uint64_t oscCommands = 0, oscRefused = 0, timecodeFired = 0;
  double longestPassMs = 0.0;
  int maxWaitMs = 100;
};

void printReport(const LiveReceiver& live, double seconds, const ControlStats& control, bool osc, bool timecode) {
  const DmxInputStats& s = live.stats();
  std::fprintf(stderr,
               "haze live: %.1f s: %llu datagrams, %llu good (%.1f/s), %llu malformed, %llu ignored, "
               "%llu late, %llu terminated, %llu unpatched universe, %llu over source limits\n",
               seconds, static_cast<unsigned long long>(s.received),
               static_cast<unsigned long long>(s.good), seconds > 0 ? s.good / seconds : 0.0,
               static_cast<unsigned long long>(s.malformedTotal()),
               static_cast<unsigned long long>(s.ignored), static_cast<unsigned long long>(s.late),
               static_cast<unsigned long long>(s.terminated),
               static_cast<unsigned long long>(s.unwatched),
               static_cast<unsigned long long>(s.exceeded));
  if (s.syncPackets || s.held)
    std::fprintf(stderr, "haze live: synchronisation: %llu sync packets, %llu frames held for them, %llu superseded before their sync, %zu still held\n",
                 static_cast<unsigned long long>(s.syncPackets), static_cast<unsigned long long>(s.held),
                 static_cast<unsigned long long>(s.superseded), live.input().syncGate().heldCount());
  if (s.foreignArtSyncs)
    std::fprintf(stderr, "haze live: ignored %llu ArtSync from addresses that send no ArtDmx (Art-Net 4: ArtSync is the ArtDmx sender's)\n",
                 static_cast<unsigned long long>(s.foreignArtSyncs));
  for (const DiscoveredSource& d : live.input().discovered()) {
    std::string list;
    int shown = 0;
    for (int u : d.universes) {
      if (shown++ == 32) {
        list += " ... (" + std::to_string(d.universes.size()) + " in all)";
        break;
      }
      list += (list.empty() ? "" : ",") + std::to_string(u);
    }
    std::fprintf(stderr, "haze live: discovered sACN source %s \"%s\" universes %s (%d of %d pages)\n",
                 d.cidString().c_str(), printable(d.name).c_str(), list.empty() ? "none" : list.c_str(), d.pages,
                 d.lastPage + 1);
  }
  if (const int polls = live.udp().artPollsAnswered(); polls > 0)
    std::fprintf(stderr, "haze live: answered %d ArtPoll%s (ArtPollReply: a visualiser with the patched universes)\n",
                 polls, polls == 1 ? "" : "s");
  if (osc)
    std::fprintf(stderr, "haze live: OSC: %llu commands done, %llu refused\n",
                 static_cast<unsigned long long>(control.oscCommands), static_cast<unsigned long long>(control.oscRefused));
  if (timecode)
    std::fprintf(stderr, "haze live: timecode: %llu ArtTimeCode packets, %llu cue firings or chases\n",
                 static_cast<unsigned long long>(s.timecodePackets), static_cast<unsigned long long>(control.timecodeFired));
  std::fprintf(stderr, "haze live: longest pass of the receive loop: %.1f ms (a pass waits up to %d ms for input)\n",
               control.longestPassMs, control.maxWaitMs);
  for (const auto& [reason, count] : s.malformed) {
    std::fprintf(stderr, "haze live: malformed %s: %llu\n", reason.c_str(),
                 static_cast<unsigned long long>(count));
  }
  for (const Error& e : s.firstMalformed) {
    std::fprintf(stderr, "haze live: dropped %s\n", e.str().c_str());
  }
  for (const DmxSourceInfo& src : live.sources()) {
    const std::string name = src.name.empty() ? "" : " \"" + printable(src.name) + "\"";
    std::fprintf(stderr, "haze live: source %s %s%s universe %d priority %d%s%s\n",
                 src.id.protocol == DmxProtocol::Sacn ? "sACN" : "Art-Net", src.id.str().c_str(),
                 name.c_str(), src.universe, src.priority, src.perSlotPriority ? " (per-slot priorities)" : "",
                 src.winning ? "" : " (outranked)");
  }
}

}  // namespace

int runLive(const Args& args) {
  std::string showPath, stateJson, renderOut, onLoss = "hold", quality = "default", exposureMode, movement = "real";
  double exposure = std::nan("");
  LiveOptions options;
  RenderJobOptions render;
  bool artNet = false, sacn = false;
  double duration = 0.0;
  int artNetPort = options.udp.artNetPort, sacnPort = options.udp.sacnPort;
  bool noPreview = false, timecode = false, noSync = false, mtc = false;
  std::string mtcFrom;
  int oscPort = -1;
  std::string cueListName, recordCue, recordLabel;
  CommandLine cli("haze live", kUsage);
  cli.flag("--artnet", artNet)
      .flag("--sacn", sacn)
      .text("--bind", options.udp.bindAddress, "an IPv4 address such as 127.0.0.1")
      .number("--duration", duration, 0, 1e7, "seconds >= 0")
      .text("--state-json", stateJson, "an output file")
      .text("--render", renderOut, "an output image (.png or .pfm)")
      .integer("--artnet-port", artNetPort, 0, 65535, "a port 0..65535")
      .integer("--sacn-port", sacnPort, 0, 65535, "a port 0..65535")
      .flag("--multicast", options.udp.multicast)
      .choice("--on-loss", onLoss, {"hold", "blackout"})
      .flag("--no-preview", noPreview)
      .choice("--movement", movement, {"real", "instant"})
      .text("--camera", render.camera, "a camera name")
      .integer("--width", render.width, 1, 16384, "a whole number 1..16384")
      .integer("--height", render.height, 1, 16384, "a whole number 1..16384")
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .number("--exposure", exposure, -100, 100, "a number of EV")
      .choice("--exposure-mode", exposureMode, {"auto", "manual"})
      .integer("--osc", oscPort, 0, 65535, "a port 0..65535")
      .flag("--timecode", timecode)
      .flag("--mtc", mtc)
      .text("--mtc-from", mtcFrom, "an ALSA sequencer address (CLIENT:PORT)")
      .text("--cue-list", cueListName, "a cue list name")
      .text("--record-cue", recordCue, "a cue number such as 10")
      .text("--label", recordLabel, "a cue label")
      .flag("--no-sync", noSync)
      .positional(showPath, "show");
  XchangeOptions xchange;
  addXchangeOptions(cli, xchange);
  if (auto done = cli.parse(args)) return *done;
  if (noPreview) options.input.acceptPreview = false;
  if (noSync) options.input.synchronise = false;
  render.exposureMode = parseExposureMode(exposureMode);
  if (!std::isnan(exposure)) render.exposureEv = static_cast<float>(exposure);
  const auto fail = [&cli](const std::string& line) { return cli.fail(line); };
  if (quality == "draft") render.quality = Quality::Draft;
  else if (quality == "default") render.quality = Quality::Default;
  else if (quality == "high") render.quality = Quality::High;
  else if (quality == "reference") render.quality = Quality::Reference;
  else return cli.usage("--quality '" + quality + "' is not one of draft|default|high|reference");
  if (!artNet && !sacn) artNet = sacn = true;
  if (oscPort > 0 && ((artNet && oscPort == artNetPort) || (sacn && oscPort == sacnPort)))
    return cli.usage("--osc " + std::to_string(oscPort) + " is the Art-Net or sACN port; expected a port of its own (e.g. 9000)");
  if (timecode && !artNet) return cli.usage("--timecode reads ArtTimeCode, which comes over Art-Net; drop --sacn or add --artnet");
  if (!recordLabel.empty() && recordCue.empty()) return cli.usage("--label names the cue --record-cue records; give --record-cue N");
  if (!recordCue.empty() && !isCueNumber(recordCue))
    return cli.usage("--record-cue '" + recordCue + "' is not a cue number; expected one like 10 or 1.5");
  options.udp.artNet = artNet;
  options.udp.sacn = sacn;
  options.udp.artNetPort = artNetPort;
  options.udp.sacnPort = sacnPort;
  options.input.merge.onLoss = onLoss == "blackout" ? LossPolicy::Blackout : LossPolicy::HoldLastLook;

  auto checked = cli.readShow(showPath);
  if (!checked) return kExitBadInput;
  Show* show = &checked->show;  // --record-cue records into it
  const ProfileSet* profiles = &checked->profiles;
  const CueList* cueList = nullptr;
  for (const CueList& l : show->cueLists)
    if (cueListName.empty() || l.name == cueListName) {
      cueList = &l;
      break;
    }
  if (!cueListName.empty() && !cueList) return fail(showPath + ": the show has no cue list \"" + cueListName + "\"");
  if (!mtcFrom.empty()) mtc = true;
  const bool playback = oscPort >= 0 || timecode || mtc;
  LivePlayback livePlayback(*show, *profiles, cueList);
  if ((timecode || mtc) && cueList &&
      std::none_of(cueList->cues.begin(), cueList->cues.end(), [](const Cue& c) { return !c.timecode.empty(); }))
    std::fprintf(stderr, "haze live: --timecode: no cue of the played list has a \"timecode\"; nothing will fire\n");

  // What the console can reach, per universe, so a fixture that ignores it is explained at once.
  const std::vector<UniverseReach> reach = dmxReach(*show, *profiles);
  printReach(reach);
  std::set<int> drivingUniverses, warnedUniverses;
  for (const UniverseReach& u : reach)
    if (!u.driven.empty()) drivingUniverses.insert(u.universe);
  uint64_t goodSeen = 0, unwatchedSeen = 0;
  // Once per universe: DMX arrives for it, and it drives nothing.
  const auto warnIdleUniverses = [&](LiveReceiver& r) {
    if (r.stats().good == goodSeen && r.stats().unwatched == unwatchedSeen) return;
    goodSeen = r.stats().good;
    unwatchedSeen = r.stats().unwatched;
    for (int u : r.stats().unwatchedUniverses)
      if (warnedUniverses.insert(u).second)
        std::fprintf(stderr, "haze live: warning: universe %d receives DMX, but no fixture of the show is patched on it\n", u);
    for (const DmxSourceInfo& s : r.sources())
      if (!drivingUniverses.count(s.universe) && warnedUniverses.insert(s.universe).second)
        std::fprintf(stderr, "haze live: warning: universe %d receives DMX, but it drives no fixture (see the lines "
                     "above for why)\n", s.universe);
  };

  auto live = LiveReceiver::open(*show, *profiles, options);
  if (!live) return fail(live.error().str());
  LiveReceiver& receiver = **live;
  // Handlers first: a test (or a user) may interrupt as soon as the ports are printed.
  struct sigaction sa {}, oldInt{}, oldTerm{};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &oldInt);
  sigaction(SIGTERM, &sa, &oldTerm);
  gStop = 0;
  if (receiver.udp().artNetPort()) {
    std::fprintf(stderr, "haze live: Art-Net on %s:%d (haze universe = Port-Address + 1)\n",
                 options.udp.bindAddress.c_str(), receiver.udp().artNetPort());
  }
  if (receiver.udp().sacnPort()) {
    std::fprintf(stderr, "haze live: sACN on %s:%d\n", options.udp.bindAddress.c_str(),
                 receiver.udp().sacnPort());
  }
  std::unique_ptr<MidiSeqInput> mtcIn;
  MtcDecoder mtcDecoder;
  if (mtc) {
    auto m = MidiSeqInput::open(mtcFrom);
    if (!m) return fail("--mtc: " + m.error().str());
    mtcIn = std::move(*m);
    std::fprintf(stderr, "haze live: MTC on %s (ALSA sequencer client \"haze\", port \"MTC in\"%s)\n",
                 mtcIn->address().c_str(), mtcFrom.empty() ? "" : ("; connected from " + mtcFrom).c_str());
  }
  std::unique_ptr<OscSocket> osc;
  if (oscPort >= 0) {
    auto o = OscSocket::open(options.udp.bindAddress, oscPort);
    if (!o) return fail(o.error().str());
    osc = std::move(*o);
    std::fprintf(stderr, "haze live: OSC on %s:%d\n", options.udp.bindAddress.c_str(), osc->port());
  }
  std::unique_ptr<XchangeService> xchangeService;  // stopped (MVR_LEAVE sent) when live ends
  if (xchange.enabled) {
    auto x = XchangeService::start(showPath, options.udp.bindAddress, xchange);
    if (!x) return fail(x.error().str());
    xchangeService = std::move(*x);
  }
  for (const std::string& note : receiver.udp().notes()) {
    std::fprintf(stderr, "haze live: %s\n", note.c_str());
  }
  if (playback)
    std::fprintf(stderr, "haze live: playing %s\n",
                 cueList ? ("cue list \"" + cueList->name + "\" (" + std::to_string(cueList->cues.size()) + " cues)").c_str()
                         : "no cue list (the show has none)");

  // OSC and timecode are read every pass; the wait for DMX is then short so they are not late.
  ControlStats control;
  constexpr uint64_t kLoggedRefusals = 20;
  const auto handleOsc = [&](std::span<const uint8_t> datagram, const std::string& from) {
    OscParse p = parseOscCommand(datagram);
    if (p.ok) {
      Result<std::string> done = livePlayback.apply(p.command, LiveReceiver::nowS());
      if (done) {
        ++control.oscCommands;
        std::fprintf(stderr, "haze live: OSC %s from %s: %s\n", printable(p.address).c_str(), from.c_str(), done->c_str());
      } else {
        p.ok = false;
        p.error = done.error().str();
      }
    }
    if (!p.ok && ++control.oscRefused <= kLoggedRefusals)
      std::fprintf(stderr, "haze live: OSC from %s refused: %s%s\n", from.c_str(), printable(p.error).c_str(),
                   control.oscRefused == kLoggedRefusals ? " (further refusals are only counted)" : "");
    return oscReply(p);
  };
  const double start = LiveReceiver::nowS();
  // The heads follow each DMX value from the moment a poll returns with it (docs/movement.md);
  // the command before it holds until then. They start where the first DMX puts them, as a rig
  // that was switched on at the console's look.
  MovementFollower heads(*show, *profiles);
  StageState commanded =
      playback ? livePlayback.stage(LiveReceiver::nowS(), receiver.state(), receiver.input().dmxFixtures()) : receiver.state();
  heads.reset(commanded, 0.0);
  bool seeded = false;
  while (!gStop) {
    const double elapsed = LiveReceiver::nowS() - start;
    if (duration > 0 && elapsed >= duration) break;
    const double leftMs = duration > 0 ? (duration - elapsed) * 1000.0 : 100.0;
    control.maxWaitMs = playback ? 5 : 100;
    const double maxWaitMs = control.maxWaitMs;
    const int waitMs = static_cast<int>(std::clamp(leftMs, 1.0, maxWaitMs));
    const double passStart = LiveReceiver::nowS();
    receiver.poll(waitMs);
    if (osc) osc->pump(handleOsc);
    if (mtcIn) {
      mtcIn->pump([&](std::span<const uint8_t> bytes) {
        for (const MtcReading& r : mtcDecoder.feed(bytes)) {
          const std::string what = livePlayback.timecode(r.time, r.fps(), LiveReceiver::nowS());
          if (what.empty()) continue;
          ++control.timecodeFired;
          std::fprintf(stderr, "haze live: MTC %s: %s\n", r.time.str().c_str(), what.c_str());
        }
      });
    }
    if (timecode) {
      for (const ArtTimeCodePacket& tc : receiver.input().takeTimecodes()) {
        const std::string what = livePlayback.timecode(tc.time, tc.fps(), LiveReceiver::nowS());
        if (what.empty()) continue;
        ++control.timecodeFired;
        std::fprintf(stderr, "haze live: timecode %s: %s\n", tc.time.str().c_str(), what.c_str());
      }
    }
    const double now = LiveReceiver::nowS() - start;
    heads.advance(commanded, now, false);
    commanded = playback ? livePlayback.stage(LiveReceiver::nowS(), receiver.state(), receiver.input().dmxFixtures())
                         : receiver.state();
    warnIdleUniverses(receiver);
    if (!seeded && receiver.stats().good > 0) {
      heads.reset(commanded, now);
      seeded = true;
    }
    // Whole passes: a pass that found nothing waited waitMs; one that found a flood did its work.
    control.longestPassMs = std::max(control.longestPassMs, (LiveReceiver::nowS() - passStart) * 1000.0);
  }
  const StageState& dmxState = receiver.poll(0);
  // What the console and the cues command; the heads get there at their speeds.
  const StageState commandedState =
      playback ? livePlayback.stage(LiveReceiver::nowS(), dmxState, receiver.input().dmxFixtures()) : dmxState;
  const StageState moved = heads.advance(commandedState, LiveReceiver::nowS() - start, false);
  const StageState& state = movement == "real" ? moved : commandedState;
  sigaction(SIGINT, &oldInt, nullptr);
  sigaction(SIGTERM, &oldTerm, nullptr);
  printReport(receiver, LiveReceiver::nowS() - start, control, osc != nullptr, timecode);
  if (mtcIn) {
    const MtcStats& m = mtcDecoder.stats();
    std::fprintf(stderr, "haze live: MTC: %llu quarter frames, %llu full frames, %llu broken cycles, %llu bad times\n",
                 static_cast<unsigned long long>(m.quarterFrames), static_cast<unsigned long long>(m.fullFrames),
                 static_cast<unsigned long long>(m.brokenCycles), static_cast<unsigned long long>(m.badTimes));
  }

  int status = 0;
  if (!stateJson.empty()) {
    const std::string text = stageStateJson(*show, *profiles, state).dump(2) + "\n";
    if (Status s = writeFileAtomically(stateJson, text, false); !s) status = fail(s.error().str());
  }
  if (!renderOut.empty()) {
    if (!livePlayback.camera().empty()) render.camera = livePlayback.camera();  // /haze/camera
    if (Status s = renderStateToFile(*show, *profiles, state, render, renderOut); !s) {
      status = fail(s.error().str());
    }
  }
  if (!recordCue.empty()) {
    // What DMX (and OSC's programmer) put on stage; fixtures nothing drove are left out, so a
    // universe the console does not send cannot wipe the tracked look.
    std::set<int> fixtures = receiver.input().dmxFixtures();
    for (const auto& [id, v] : livePlayback.programmer()) fixtures.insert(id);
    if (fixtures.empty()) {
      status = fail("--record-cue " + recordCue + ": no fixture received DMX; nothing recorded and " + showPath +
                    " left as it was");
    } else {
      // The playback above references the show; it is not used after this point.
      Result<std::string> rec =
          recordLiveCue(*show, *profiles, commandedState, fixtures,
                        LiveRecord{cueList ? cueList->name : "", recordCue, recordLabel});
      if (!rec) status = fail(showPath + ": " + rec.error().str());
      else std::fprintf(stderr, "haze live: %s\n", rec->c_str());
    }
  }
  return status;
}

}  // namespace haze
