// haze live SHOW [--artnet] [--sacn] [--bind ADDR] [--duration S] [--state-json OUT]
//                [--render OUT.png]: DMX in from a console, headless. Receives for S seconds
// (or until SIGINT/SIGTERM), then writes the fixtures' final states and/or renders them, and
// prints what arrived (good packets, drops by reason, rate, sources) to stderr.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/render_job.h"
#include "app/state_json.h"
#include "shows/dmx/udp_receiver.h"
#include "shows/movement.h"
#include "fixtures/core/atomic_file.h"
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
    "Listens for Art-Net (UDP 6454) and sACN E1.31 (UDP 5568); neither flag means both.\n"
    "--bind: the local IPv4 address to listen on (default 127.0.0.1: this machine only).\n"
    "sACN universe N is haze universe N; Art-Net Port-Address P (Net:Sub-Net:Universe) is\n"
    "haze universe P + 1, so Art-Net 0:0:0 drives patch universe 1.\n"
    "sACN multicast (239.255.hi.lo) is joined for the patched universes when --bind is not a\n"
    "loopback address, or with --multicast. Port 0 picks a free port (printed on stderr).\n"
    "--duration 0 (the default) runs until Ctrl-C.\n"
    "--movement real|instant: heads follow DMX at the fixtures' speeds (default) or jump at once.\n";

volatile std::sig_atomic_t gStop = 0;
void onSignal(int) { gStop = 1; }

std::string printable(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += (c >= 0x20 && c < 0x7F) ? static_cast<char>(c) : '?';
  return out;
}

void printReport(const LiveReceiver& live, double seconds) {
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
  if (const int polls = live.udp().artPollsAnswered(); polls > 0)
    std::fprintf(stderr, "haze live: answered %d ArtPoll%s (ArtPollReply: a visualiser with the patched universes)\n",
                 polls, polls == 1 ? "" : "s");
  for (const auto& [reason, count] : s.malformed) {
    std::fprintf(stderr, "haze live: malformed %s: %llu\n", reason.c_str(),
                 static_cast<unsigned long long>(count));
  }
  for (const Error& e : s.firstMalformed) {
    std::fprintf(stderr, "haze live: dropped %s\n", e.str().c_str());
  }
  for (const DmxSourceInfo& src : live.sources()) {
    const std::string name = src.name.empty() ? "" : " \"" + printable(src.name) + "\"";
    std::fprintf(stderr, "haze live: source %s %s%s universe %d priority %d%s\n",
                 src.id.protocol == DmxProtocol::Sacn ? "sACN" : "Art-Net", src.id.str().c_str(),
                 name.c_str(), src.universe, src.priority, src.winning ? "" : " (outranked)");
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
  bool noPreview = false;
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
      .positional(showPath, "show");
  if (auto done = cli.parse(args)) return *done;
  if (noPreview) options.input.acceptPreview = false;
  render.exposureMode = parseExposureMode(exposureMode);
  if (!std::isnan(exposure)) render.exposureEv = static_cast<float>(exposure);
  const auto fail = [&cli](const std::string& line) { return cli.fail(line); };
  if (quality == "draft") render.quality = Quality::Draft;
  else if (quality == "default") render.quality = Quality::Default;
  else if (quality == "high") render.quality = Quality::High;
  else if (quality == "reference") render.quality = Quality::Reference;
  else return fail("--quality '" + quality + "' is not one of draft|default|high|reference");
  if (!artNet && !sacn) artNet = sacn = true;
  options.udp.artNet = artNet;
  options.udp.sacn = sacn;
  options.udp.artNetPort = artNetPort;
  options.udp.sacnPort = sacnPort;
  options.input.merge.onLoss = onLoss == "blackout" ? LossPolicy::Blackout : LossPolicy::HoldLastLook;

  Result<Show> show = loadShow(showPath);
  if (!show) return fail(show.error().str());
  Result<ProfileSet> profiles = loadProfiles(*show);
  if (!profiles) return fail(profiles.error().str());

  // Patched fixtures that DMX cannot drive are named once, so a dark fixture is explained.
  for (const FixtureDef& f : show->fixtures) {
    if (!f.patch) continue;
    auto p = profiles->find(f.profile);
    const bool hasMode = p != profiles->end() && p->second &&
                         std::any_of(p->second->modes.begin(), p->second->modes.end(),
                                     [&](const DmxMode& m) { return m.name == f.mode || f.mode.empty(); });
    if (!hasMode) {
      std::fprintf(stderr, "haze live: fixture %d: profile \"%s\" has no DMX mode \"%s\"; it stays dark\n",
                   f.id, f.profile.c_str(), f.mode.c_str());
    }
  }

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
  for (const std::string& note : receiver.udp().notes()) {
    std::fprintf(stderr, "haze live: %s\n", note.c_str());
  }

  const double start = LiveReceiver::nowS();
  // The heads follow each DMX value from the moment a poll returns with it (docs/movement.md);
  // the command before it holds until then. They start where the first DMX puts them, as a rig
  // that was switched on at the console's look.
  MovementFollower heads(*show, *profiles);
  StageState commanded = receiver.state();
  heads.reset(commanded, 0.0);
  bool seeded = false;
  while (!gStop) {
    const double elapsed = LiveReceiver::nowS() - start;
    if (duration > 0 && elapsed >= duration) break;
    const double leftMs = duration > 0 ? (duration - elapsed) * 1000.0 : 100.0;
    receiver.poll(static_cast<int>(std::clamp(leftMs, 1.0, 100.0)));
    const double now = LiveReceiver::nowS() - start;
    heads.advance(commanded, now, false);
    commanded = receiver.state();
    if (!seeded && receiver.stats().good > 0) {
      heads.reset(commanded, now);
      seeded = true;
    }
  }
  const StageState& dmxState = receiver.poll(0);
  const StageState moved = heads.advance(dmxState, LiveReceiver::nowS() - start, false);
  const StageState& state = movement == "real" ? moved : dmxState;
  sigaction(SIGINT, &oldInt, nullptr);
  sigaction(SIGTERM, &oldTerm, nullptr);
  printReport(receiver, LiveReceiver::nowS() - start);

  int status = 0;
  if (!stateJson.empty()) {
    const std::string text = stageStateJson(*show, *profiles, state).dump(2) + "\n";
    if (Status s = writeFileAtomically(stateJson, text, false); !s) status = fail(s.error().str());
  }
  if (!renderOut.empty()) {
    if (Status s = renderStateToFile(*show, *profiles, state, render, renderOut); !s) {
      status = fail(s.error().str());
    }
  }
  return status;
}

}  // namespace haze
