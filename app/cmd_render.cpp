// haze render SHOW [--cue N | --all-cues] [--at S] [--list NAME] [--camera NAME]
//                  [--width W --height H] [--quality Q] [--exposure EV] [--exposure-mode auto|manual]
//                  [--bloom F] -o OUT.(png|pfm) | DIR/
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/render_session.h"
#include "shows/movement.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze render SHOW [--cue N | --all-cues] [--at S] [--list NAME] [--camera NAME]\n"
    "                   [--width W --height H] [--quality draft|default|high|reference] [--exposure EV]\n"
    "                   [--exposure-mode auto|manual] [--bloom F]\n"
    "                   -o OUT.png|OUT.pfm (one image) | -o DIR/ (with --all-cues)\n"
    "Without --cue the first cue is rendered; --at S renders S seconds after its GO.\n"
    "PNGs are metered like a camera (auto, the default) and --exposure EV is an offset from the\n"
    "metered exposure; with --exposure-mode manual it is absolute (EV 0: 50 cd/m^2 maps to 1).\n"
    "A camera's \"exposure\" in the show is used unless these are given. PFMs are never exposed.\n"
    "--bloom F spreads the fraction F (0..1) of the light as lens glare in PNGs; PFMs stay radiometric.\n"
    "--movement real|instant: pan, tilt and zoom at the fixtures' speeds (default) or at once.\n"
    "--cells separate|merged: one beam per cell (default), or a fixture's alike cells as one beam.\n";

}  // namespace

int runRender(const Args& args) {
  std::string showPath, cue, list, out, camera, quality = "default", exposureMode, movement = "real", cells = "separate";
  double at = -1.0, exposure = std::nan(""), bloom = 0.0;
  int width = 1280, height = 720;
  bool allCues = false;
  CommandLine cli("haze render", kUsage);
  cli.text("--cue", cue, "a cue number")
      .flag("--all-cues", allCues)
      .number("--at", at, 0.0, 1e9, "seconds >= 0")
      .text("--list", list, "a cue list name")
      .text("--camera", camera, "a camera name")
      .integer("--width", width, 1, 16384, "a whole number 1..16384")
      .integer("--height", height, 1, 16384, "a whole number 1..16384")
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .number("--exposure", exposure, -100, 100, "a number of EV")
      .choice("--exposure-mode", exposureMode, {"auto", "manual"})
      .number("--bloom", bloom, 0, 1, "a fraction 0..1")
      .choice("--movement", movement, {"real", "instant"})
      .choice("--cells", cells, {"separate", "merged"})
      .text("-o|--output", out, "a file or a folder")
      .positional(showPath, "show");
  if (auto done = cli.parse(args)) return *done;
  const auto fail = [&cli](const std::string& line) { return cli.fail(line); };
  if (out.empty()) return fail("no output given: -o OUT.png, -o OUT.pfm, or -o DIR/ with --all-cues");
  if (allCues && !cue.empty()) return fail("--cue and --all-cues exclude each other");
  auto q = parseQuality(quality);
  if (!q) return fail(q.error().str());

  auto show = loadShow(showPath);
  if (!show) return fail(show.error().str());
  auto profiles = loadProfiles(*show);
  if (!profiles) return fail(profiles.error().str());
  const CueList* cueList = show->findCueList(list);
  if (!cueList) return fail(showPath + ": no cue list" + (list.empty() ? "" : " named '" + list + "'"));
  if (cueList->cues.empty()) return fail(showPath + ": cue list '" + cueList->name + "' has no cues");

  RenderJobOptions options{.camera = camera, .width = static_cast<int>(width), .height = static_cast<int>(height),
                           .quality = *q, .exposureMode = parseExposureMode(exposureMode),
                           .bloom = static_cast<float>(bloom), .mergeCells = cells == "merged"};
  if (!std::isnan(exposure)) options.exposureEv = static_cast<float>(exposure);
  auto session = RenderSession::open(*show, options);
  if (!session) return fail(session.error().str());

  auto renderCue = [&](size_t index, const std::filesystem::path& file) -> bool {
    const StageState state = at < 0 ? trackedState(*show, *profiles, *cueList, index)
                             : movement == "real" ? movingStateAt(*show, *profiles, *cueList, index, at)
                                                  : stateAt(*show, *profiles, *cueList, index, at);
    const Status s = (*session)->renderToFile(*show, *profiles, state, file);
    if (!s) {
      fail(s.error().str());
      return false;
    }
    return true;
  };

  if (allCues) {
    const std::filesystem::path dir(out);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return fail(out + ": cannot create the folder: " + ec.message());
    for (size_t i = 0; i < cueList->cues.size(); ++i) {
      const auto file = dir / ("cue-" + cueList->cues[i].number + ".png");
      if (!renderCue(i, file)) return 1;
      std::printf("%s\n", file.string().c_str());
    }
    return 0;
  }
  size_t index = 0;
  if (!cue.empty()) {
    auto found = findCue(*cueList, cue);
    if (!found) return fail(found.error().str());
    index = *found;
  }
  return renderCue(index, out) ? 0 : 1;
}

}  // namespace haze
