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
#include "shows/frame/live_session.h"
#include "shows/frame/live_record.h"
#include "shows/frame/state_json.h"
#include "app/xchange_station.h"
#include "fixtures/core/atomic_file.h"
#include "shows/cue_number.h"
#include "shows/id_ranges.h"
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

// SIGINT and SIGTERM end the receive loop instead of the program while this lives.
class StopOnSignals {
 public:
  StopOnSignals() {
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &oldInt_);
    sigaction(SIGTERM, &sa, &oldTerm_);
    gStop = 0;
  }
  ~StopOnSignals() {
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  struct sigaction oldInt_ {}, oldTerm_ {};
};

// What arrived and what was done with it, on exit.
void printReport(const LiveSession& session, bool timecode) {
  const LiveReceiver& live = session.receiver();
  const LiveControlStats& control = session.stats();
  const double seconds = session.secondsSinceStart();
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
  if (session.oscPort())
    std::fprintf(stderr, "haze live: OSC: %llu commands done, %llu refused\n",
                 static_cast<unsigned long long>(control.oscCommands), static_cast<unsigned long long>(control.oscRefused));
  if (timecode)
    std::fprintf(stderr, "haze live: timecode: %llu ArtTimeCode packets, %llu cue firings or chases\n",
                 static_cast<unsigned long long>(s.timecodePackets), static_cast<unsigned long long>(control.timecodeFired));
  std::fprintf(stderr, "haze live: longest pass of the receive loop: %.1f ms (a pass waits up to %d ms for input)\n",
               control.longestPassMs, session.maxWaitMs());
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
  if (session.mtcOpen()) {
    const MtcStats& m = session.mtcStats();
    std::fprintf(stderr, "haze live: MTC: %llu quarter frames, %llu full frames, %llu broken cycles, %llu bad times\n",
                 static_cast<unsigned long long>(m.quarterFrames), static_cast<unsigned long long>(m.fullFrames),
                 static_cast<unsigned long long>(m.brokenCycles), static_cast<unsigned long long>(m.badTimes));
  }
}

// What the command line says.
struct LiveArgs {
  std::string showPath, stateJson, renderOut, onLoss = "hold", quality = "default", exposureMode, movement = "real";
  double exposure = std::nan("");
  LiveInputs inputs;
  RenderJobOptions render;
  bool artNet = false, sacn = false;
  double duration = 0.0;
  int artNetPort = inputs.dmx.udp.artNetPort, sacnPort = inputs.dmx.udp.sacnPort;
  bool noPreview = false, noSync = false;
  std::string cueListName, recordCue, recordLabel;
  XchangeOptions xchange;  // --mvr-xchange and its options (app/xchange_station.h)
  bool playback() const { return inputs.oscPort >= 0 || inputs.artTimecode || inputs.mtc; }
};

// Parses and checks the options against each other; an exit status when that is all (help, a
// usage error).
std::optional<int> parseLiveArgs(const Args& args, CommandLine& cli, LiveArgs& a) {
  LiveOptions& options = a.inputs.dmx;
  RenderJobOptions& render = a.render;
  cli.flag("--artnet", a.artNet)
      .flag("--sacn", a.sacn)
      .text("--bind", options.udp.bindAddress, "an IPv4 address such as 127.0.0.1")
      .number("--duration", a.duration, 0, 1e7, "seconds >= 0")
      .text("--state-json", a.stateJson, "an output file")
      .text("--render", a.renderOut, "an output image (.png or .pfm)")
      .integer("--artnet-port", a.artNetPort, 0, 65535, "a port 0..65535")
      .integer("--sacn-port", a.sacnPort, 0, 65535, "a port 0..65535")
      .flag("--multicast", options.udp.multicast)
      .choice("--on-loss", a.onLoss, {"hold", "blackout"})
      .flag("--no-preview", a.noPreview)
      .choice("--movement", a.movement, {"real", "instant"})
      .text("--camera", render.camera, "a camera name")
      .integer("--width", render.width, 1, 16384, "a whole number 1..16384")
      .integer("--height", render.height, 1, 16384, "a whole number 1..16384")
      .choice("--quality", a.quality, {"draft", "default", "high", "reference"})
      .number("--exposure", a.exposure, -100, 100, "a number of EV")
      .choice("--exposure-mode", a.exposureMode, {"auto", "manual"})
      .integer("--osc", a.inputs.oscPort, 0, 65535, "a port 0..65535")
      .flag("--timecode", a.inputs.artTimecode)
      .flag("--mtc", a.inputs.mtc)
      .text("--mtc-from", a.inputs.mtcFrom, "an ALSA sequencer address (CLIENT:PORT)")
      .text("--cue-list", a.cueListName, "a cue list name")
      .text("--record-cue", a.recordCue, "a cue number such as 10")
      .text("--label", a.recordLabel, "a cue label")
      .flag("--no-sync", a.noSync)
      .positional(a.showPath, "show");
  addXchangeOptions(cli, a.xchange);
  if (auto done = cli.parse(args)) return *done;
  if (a.noPreview) options.input.acceptPreview = false;
  if (a.noSync) options.input.synchronise = false;
  render.exposureMode = parseExposureMode(a.exposureMode);
  if (!std::isnan(a.exposure)) render.exposureEv = static_cast<float>(a.exposure);
  if (a.quality == "draft") render.quality = Quality::Draft;
  else if (a.quality == "default") render.quality = Quality::Default;
  else if (a.quality == "high") render.quality = Quality::High;
  else if (a.quality == "reference") render.quality = Quality::Reference;
  else return cli.usage("--quality '" + a.quality + "' is not one of draft|default|high|reference");
  if (!a.artNet && !a.sacn) a.artNet = a.sacn = true;
  const int oscPort = a.inputs.oscPort;
  if (oscPort > 0 && ((a.artNet && oscPort == a.artNetPort) || (a.sacn && oscPort == a.sacnPort)))
    return cli.usage("--osc " + std::to_string(oscPort) + " is the Art-Net or sACN port; expected a port of its own (e.g. 9000)");
  if (a.inputs.artTimecode && !a.artNet) return cli.usage("--timecode reads ArtTimeCode, which comes over Art-Net; drop --sacn or add --artnet");
  if (!a.recordLabel.empty() && a.recordCue.empty()) return cli.usage("--label names the cue --record-cue records; give --record-cue N");
  if (!a.recordCue.empty() && !isCueNumber(a.recordCue))
    return cli.usage("--record-cue '" + a.recordCue + "' is not a cue number; expected one like 10 or 1.5");
  options.udp.artNet = a.artNet;
  options.udp.sacn = a.sacn;
  options.udp.artNetPort = a.artNetPort;
  options.udp.sacnPort = a.sacnPort;
  options.input.merge.onLoss = a.onLoss == "blackout" ? LossPolicy::Blackout : LossPolicy::HoldLastLook;
  if (!a.inputs.mtcFrom.empty()) a.inputs.mtc = true;
  return std::nullopt;
}

// Passes until SIGINT/SIGTERM or the end of --duration. OSC and timecode are read every pass;
// the wait for DMX is then short so they are not late.
void receiveUntilStopped(LiveSession& session, double duration) {
  const double start = LiveSession::clockS();
  while (!gStop) {
    const double elapsed = LiveSession::clockS() - start;
    if (duration > 0 && elapsed >= duration) break;
    const double leftMs = duration > 0 ? (duration - elapsed) * 1000.0 : 100.0;
    session.pass(static_cast<int>(std::clamp(leftMs, 1.0, static_cast<double>(session.maxWaitMs()))));
  }
}

// --state-json, --render and --record-cue from the session's last stage; the exit status.
int writeLiveOutputs(const LiveArgs& a, CommandLine& cli, Show& show, const ProfileSet& profiles,
                     const CueList* cueList, LiveSession& session) {
  // What the console and the cues command; with --movement real, where the heads got to.
  const StageState& state = a.movement == "real" ? session.moved() : session.commanded();
  int status = 0;
  if (!a.stateJson.empty()) {
    const std::string text = stageStateJson(show, profiles, state).dump(2) + "\n";
    if (Status s = writeFileAtomically(a.stateJson, text, false); !s) status = cli.fail(s.error().str());
  }
  if (!a.renderOut.empty()) {
    RenderJobOptions render = a.render;
    if (!session.camera().empty()) render.camera = session.camera();  // /haze/camera
    if (Status s = renderStateToFile(show, profiles, state, render, a.renderOut); !s) status = cli.fail(s.error().str());
  }
  if (a.recordCue.empty()) return status;
  // What DMX (and OSC's programmer) put on stage; fixtures nothing drove are left out, so a
  // universe the console does not send cannot wipe the tracked look.
  std::set<int> fixtures = session.receiver().input().dmxFixtures();
  for (const auto& [id, v] : session.programmer()) fixtures.insert(id);
  if (fixtures.empty())
    return cli.fail("--record-cue " + a.recordCue + ": no fixture received DMX; nothing recorded and " + a.showPath +
                    " left as it was");
  // The session's playback references the show; it is not used after this point.
  Result<std::string> rec = recordLiveCue(show, profiles, session.commanded(), fixtures,
                                          LiveRecord{cueList ? cueList->name : "", a.recordCue, a.recordLabel});
  if (!rec) return cli.fail(a.showPath + ": " + rec.error().str());
  std::fprintf(stderr, "haze live: %s\n", rec->c_str());
  return status;
}

const CueList* findCueList(const Show& show, const std::string& name) {
  for (const CueList& l : show.cueLists)
    if (name.empty() || l.name == name) return &l;
  return nullptr;
}

}  // namespace

int runLive(const Args& args) {
  LiveArgs a;
  CommandLine cli("haze live", kUsage);
  if (auto done = parseLiveArgs(args, cli, a)) return *done;
  auto checked = cli.readShow(a.showPath);
  if (!checked) return kExitBadInput;
  Show& show = checked->show;  // --record-cue records into it
  const ProfileSet& profiles = checked->profiles;
  const CueList* cueList = findCueList(show, a.cueListName);
  if (!a.cueListName.empty() && !cueList) return cli.fail(a.showPath + ": the show has no cue list \"" + a.cueListName + "\"");
  const auto log = [](const std::string& line) { std::fprintf(stderr, "haze live: %s\n", line.c_str()); };
  LiveSession session(show, profiles, {.cueList = cueList, .playback = a.playback(), .followHeads = a.movement == "real"}, log);
  if ((a.inputs.artTimecode || a.inputs.mtc) && cueList &&
      std::none_of(cueList->cues.begin(), cueList->cues.end(), [](const Cue& c) { return !c.timecode.empty(); }))
    log("--timecode: no cue of the played list has a \"timecode\"; nothing will fire");
  // What the console can reach, per universe, so a fixture that ignores it is explained at once.
  printReach(session.reach());
  {
    // Handlers first: a test (or a user) may interrupt as soon as the ports are printed.
    const StopOnSignals stop;
    if (Status s = session.listen(a.inputs); !s) return cli.fail(s.error().str());
    std::unique_ptr<XchangeService> xchange;  // stopped (MVR_LEAVE sent) when the loop ends
    if (a.xchange.enabled) {
      auto x = XchangeService::start(a.showPath, a.inputs.dmx.udp.bindAddress, a.xchange);
      if (!x) return cli.fail(x.error().str());
      xchange = std::move(*x);
    }
    if (a.playback())
      log("playing " + (cueList ? "cue list \"" + cueList->name + "\" (" + std::to_string(cueList->cues.size()) + " cues)"
                                : std::string("no cue list (the show has none)")));
    receiveUntilStopped(session, a.duration);
    session.finish();
  }
  printReport(session, a.inputs.artTimecode);
  return writeLiveOutputs(a, cli, show, profiles, cueList, session);
}

}  // namespace haze
