// haze render SHOW [--cue N | --all-cues] [--at S] [--list NAME] [--camera NAME]
//                  [--width W --height H] [--quality Q] [--exposure EV] [--bloom F] -o OUT.(png|pfm) | DIR/
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/commands.h"
#include "app/render_session.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze render SHOW [--cue N | --all-cues] [--at S] [--list NAME] [--camera NAME]\n"
    "                   [--width W --height H] [--quality draft|default|high|reference] [--exposure EV]\n"
    "                   [--bloom F] -o OUT.png|OUT.pfm (one image) | -o DIR/ (with --all-cues)\n"
    "Without --cue the first cue is rendered; --at S renders S seconds after its GO.\n"
    "--bloom F spreads the fraction F (0..1) of the light as lens glare in PNGs; PFMs stay radiometric.\n";

int fail(const std::string& line) {
  std::fprintf(stderr, "haze render: %s\n", line.c_str());
  return 1;
}

bool parseNumber(const std::string& s, double& out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace

int runRender(const Args& args) {
  std::string showPath, cue, list, out, camera, quality = "default";
  double at = -1.0, exposure = 0.0, bloom = 0.0, width = 1280, height = 720;
  bool allCues = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](std::string& dst) {
      if (i + 1 >= args.size()) return false;
      dst = args[++i];
      return true;
    };
    auto number = [&](double& dst) {
      std::string s;
      return value(s) && parseNumber(s, dst);
    };
    if (a == "--cue") {
      if (!value(cue)) return fail("--cue needs a cue number");
    } else if (a == "--all-cues") {
      allCues = true;
    } else if (a == "--at") {
      if (!number(at) || at < 0) return fail("--at needs seconds >= 0");
    } else if (a == "--list") {
      if (!value(list)) return fail("--list needs a cue list name");
    } else if (a == "--camera") {
      if (!value(camera)) return fail("--camera needs a camera name");
    } else if (a == "--width") {
      if (!number(width) || width < 1 || width > 16384) return fail("--width needs a whole number 1..16384");
    } else if (a == "--height") {
      if (!number(height) || height < 1 || height > 16384) return fail("--height needs a whole number 1..16384");
    } else if (a == "--quality") {
      if (!value(quality)) return fail("--quality needs draft|default|high|reference");
    } else if (a == "--exposure") {
      if (!number(exposure)) return fail("--exposure needs a number of EV");
    } else if (a == "--bloom") {
      if (!number(bloom) || bloom < 0.0 || bloom > 1.0) return fail("--bloom needs a fraction 0..1");
    } else if (a == "-o" || a == "--output") {
      if (!value(out)) return fail("-o needs a file or a folder");
    } else if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (!a.empty() && a[0] == '-') {
      return fail("unknown option '" + a + "' (see haze render --help)");
    } else if (showPath.empty()) {
      showPath = a;
    } else {
      return fail("unexpected argument '" + a + "' (one show at a time)");
    }
  }
  if (showPath.empty()) return fail("no show given (see haze render --help)");
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
                           .quality = *q};
  auto session = RenderSession::open(*show, options);
  if (!session) return fail(session.error().str());

  auto renderCue = [&](size_t index, const std::filesystem::path& file) -> bool {
    const StageState state = at >= 0 ? stateAt(*show, *profiles, *cueList, index, at)
                                     : trackedState(*show, *profiles, *cueList, index);
    const Status s = (*session)->renderToFile(*show, *profiles, state, file, static_cast<float>(exposure),
                                                    static_cast<float>(bloom));
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
