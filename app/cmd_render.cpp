// haze render SHOW [--cue N | --all-cues | --timecode hh:mm:ss:ff] [--at S] [--list NAME] [--camera NAME]
//                  [--width W --height H] [--quality Q] [--exposure EV] [--exposure-mode auto|manual]
//                  [--bloom F] [--exr-pixel half|float] -o OUT.(png|pfm|exr) | DIR/
// haze render SHOW --play LIST=CUE[@MASTER][+GO_S] [--play ...] [--at S] ... -o OUT (shows/frame/list_plays.h)
// haze render SHOW --video OUT.mp4|OUT-%05d.png|OUT-%05d.exr [--from CUE] [--to CUE] [--fps N]
//                  [--hold S] [--duration S] [--codec NAME] [--progress] [--timecode START] (docs/output.md)
//                  [--frames A-B] [--resume] (a part of an image sequence, for a render farm)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/command_line.h"
#include "app/commands.h"
#include "app/exposure_lock.h"
#include "shows/frame/list_plays.h"
#include "app/progress.h"
#include "app/render_session.h"
#include "shows/hazer_levels.h"
#include "shows/movement.h"
#include "app/render_video.h"
#include "shows/playback.h"
#include "shows/show.h"
#include "shows/frame/live_playback.h"
#include "shows/timecode.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze render SHOW [--cue N | --all-cues | --timecode hh:mm:ss:ff] [--at S] [--list NAME] [--camera NAME]\n"
    "                   [--width W --height H] [--quality draft|default|high|reference] [--exposure EV]\n"
    "                   [--exposure-mode auto|manual|per-frame] [--bloom F] [--exr-pixel half|float] [--particles|--no-particles]\n"
    "                   -o OUT.png|OUT.pfm|OUT.exr (one image) | -o DIR/ (with --all-cues)\n"
    "       haze render SHOW --video OUT.mp4|OUT-%05d.png|OUT-%05d.exr [--list NAME] [--from CUE] [--to CUE]\n"
    "                   [--fps N] [--hold S] [--duration S] [--codec NAME] [--caption] [--progress]\n"
    "                   [--timeline FILE.json | --timecode hh:mm:ss:ff] [--frames A-B] [--resume]\n"
    "                   (and the options above)\n"
    "       haze render SHOW --play LIST=CUE[@MASTER][+GO_S] [--play ...] [--at S] -o OUT (and the options above)\n"
    "Without --cue the first cue is rendered; --at S renders S seconds after its GO.\n"
    "--play plays several cue lists at once, as haze state --play (docs/shows.md): intensity HTP,\n"
    "the rest LTP; --at S counts from 0 (without it: every fade done).\n"
    "PNGs are metered like a camera (auto, the default) and --exposure EV is an offset from the\n"
    "metered exposure; with --exposure-mode manual it is absolute (EV 0: 50 cd/m^2 maps to 1).\n"
    "A camera's \"exposure\" in the show is used unless these are given. PFMs are never exposed.\n"
    "A --video or --all-cues run is metered once, on its brightest cue, and holds that exposure (a\n"
    "fade darkens as on stage); --exposure-mode per-frame meters every image instead.\n"
    "--bloom F spreads the fraction F (0..1) of the light as lens glare in PNGs; PFMs stay radiometric.\n"
    "EXRs hold the same radiometric L as PFMs (cd/m^2, linear Rec. 709), as half (the default) or\n"
    "float (--exr-pixel float), with the show and cue in the header's comments.\n"
    "--video plays cues --from..--to (default: the whole list) as on stage: GO on the first at 0 s,\n"
    "follows fire by themselves, after a cue without one the operator waits --hold S (default 2)\n"
    "after its fade, then GOes. --duration S cuts the video at S seconds. H.264 (libx264) in MP4 at\n"
    "--fps N (default 25); a name with %05d writes one PNG or EXR per frame instead. --caption burns\n"
    "the cue number, label and time into video and PNG frames (never into EXRs). --timeline FILE.json\n"
    "gives the GO times: {\"go\": [{\"cue\": \"1\", \"at\": 0}, {\"cue\": \"2\", \"at\": 8.5}], \"end\": 20}.\n"
    "--timecode T renders what the list's timecoded cues give at T, as `haze live --timecode` shows\n"
    "on a jump to T (the last cue at or before T, its fade finished; the defaults before the first);\n"
    "with --video, timecode runs from T and cues fire at their times with their fades.\n"
    "--timecode-rate 24|25|30 (default 25): the frames of a timecode per second.\n"
    "--frames A-B renders frames A to B (from 0) of an image sequence, each exactly as a run of the whole\n"
    "video draws it (the timeline is played from frame 0, the exposure metered on the whole range), so\n"
    "ranges rendered apart, on one machine or many (haze farm), join into the whole video. --resume\n"
    "skips a frame whose file is already there and decodes completely; a cut-short one is redone.\n"
    "--progress reports progress on stderr even when it is not a terminal (it always is on one).\n"
    "--movement real|instant: pan, tilt and zoom at the fixtures' speeds (default) or at once (--at, --video).\n"
    "--cells separate|merged: one beam per cell (default), or a fixture's alike cells as one beam.\n"
    "--no-bodies leaves the fixtures' housings out (docs/fixtures.md, \"Bodies\").\n"
    "--shadows soft|hard: shadows softened by each lens disc or point lights' (default: the show's\n"
    "atmosphere.shadows, soft unless it says hard; docs/physics.md, \"Soft shadows\").\n"
    "--particles draws visible dust in the beams (the show's atmosphere.particles, on) and --no-particles\n"
    "leaves it out; without either a PNG follows the show and a PFM or EXR has none (docs/rendering.md).\n";

std::string secondsText(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

}  // namespace

int runRender(const Args& args) {
  std::string showPath, cue, list, out, camera, quality = "default", exposureMode, exrPixel = "half", movement = "real",
                                                       cells = "separate", shadows;
  double at = -1.0, exposure = std::nan(""), bloom = 0.0;
  int width = 1280, height = 720;
  bool allCues = false, progress = false, caption = false, noBodies = false, particlesOn = false, particlesOff = false;
  std::string video, from, to, codec = "libx264", timelineFile, timecodeText, timecodeRate = "25", frameRange;
  bool resume = false;
  double hold = 2.0, duration = 0.0;
  int fps = 25;
  std::vector<ListPlay> plays;
  std::string playError;
  CommandLine cli("haze render", kUsage);
  cli.custom("--play", "LIST=CUE[@MASTER][+GO_S]", [&](const std::string& v) {
    auto p = parseListPlay(v);
    if (!p && playError.empty()) playError = p.error().message;
    if (p) plays.push_back(*p);
    return true;
  });
  cli.text("--cue", cue, "a cue number")
      .flag("--all-cues", allCues)
      .number("--at", at, 0.0, 1e9, "seconds >= 0")
      .text("--list", list, "a cue list name")
      .text("--camera", camera, "a camera name")
      .integer("--width", width, 1, 16384, "a whole number 1..16384")
      .integer("--height", height, 1, 16384, "a whole number 1..16384")
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .number("--exposure", exposure, -100, 100, "a number of EV")
      .choice("--exposure-mode", exposureMode, {"auto", "manual", "per-frame"})
      .number("--bloom", bloom, 0, 1, "a fraction 0..1")
      .choice("--movement", movement, {"real", "instant"})
      .choice("--cells", cells, {"separate", "merged"})
      .choice("--shadows", shadows, {"soft", "hard"})
      .choice("--exr-pixel", exrPixel, {"half", "float"})
      .text("-o|--output", out, "a file or a folder")
      .text("--video", video, "a video file (OUT.mp4) or an image sequence (OUT-%05d.png)")
      .text("--from", from, "a cue number")
      .text("--to", to, "a cue number")
      .integer("--fps", fps, 1, 240, "frames per second, 1..240")
      .number("--hold", hold, 0, 3600, "seconds 0..3600")
      .number("--duration", duration, 0, 86400, "seconds 0..86400")
      .text("--codec", codec, "an FFmpeg encoder name")
      .text("--frames", frameRange, "frames A-B of the video, from 0")
      .flag("--resume", resume)
      .flag("--progress", progress)
      .flag("--caption", caption)
      .flag("--no-bodies", noBodies)
      .flag("--particles", particlesOn)
      .flag("--no-particles", particlesOff)
      .text("--timeline", timelineFile, "a JSON file of GO times")
      .text("--timecode", timecodeText, "a timecode hh:mm:ss:ff")
      .choice("--timecode-rate", timecodeRate, {"24", "25", "30"})
      .positional(showPath, "show");
  if (auto done = cli.parse(args)) return *done;
  const auto fail = [&cli](const std::string& line) { return cli.fail(line); };
  if (!playError.empty()) return cli.usage("--play " + playError);
  if (!plays.empty() && (!video.empty() || allCues || !cue.empty() || !list.empty() || !timecodeText.empty()))
    return cli.usage("--play renders one still of the lists it names; expected no --video, --all-cues, --cue, --list or "
                "--timecode with it");
  if (!video.empty() && (!out.empty() || allCues || !cue.empty() || at >= 0))
    return cli.usage("--video renders a cue range (--from, --to): -o, --all-cues, --cue and --at are for stills");
  if (video.empty() && (!from.empty() || !to.empty()))
    return cli.usage("--from and --to choose the cues of a --video");
  std::optional<FrameRange> frames;
  if (!frameRange.empty()) {
    auto parsed = parseFrameRange(frameRange);
    if (!parsed) return cli.usage(parsed.error().message);
    frames = *parsed;
  }
  if ((frames || resume) && video.empty())
    return cli.usage("--frames and --resume render part of a --video image sequence (OUT-%05d.png)");
  if (out.empty() && video.empty())
    return cli.usage("no output given: -o OUT.png|OUT.pfm|OUT.exr, -o DIR/ with --all-cues, or --video OUT.mp4");
  if (allCues && !cue.empty()) return cli.usage("--cue and --all-cues exclude each other");
  std::optional<Timecode> timecode;
  const int rate = std::stoi(timecodeRate);
  if (!timecodeText.empty()) {
    timecode = parseTimecode(timecodeText);
    if (!timecode || timecode->frames >= rate)
      return cli.usage("--timecode: expected hh:mm:ss:ff within a day, frames below " + timecodeRate + ", got '" +
                  timecodeText + "'");
    if (allCues || !cue.empty() || at >= 0) return cli.usage("--timecode chooses the moment itself: no --cue, --all-cues or --at");
    if (!from.empty() || !to.empty() || !timelineFile.empty())
      return cli.usage("--timecode plays the cues at their timecodes: no --from, --to or --timeline with it");
  }
  auto q = parseQuality(quality);
  if (!q) return fail(q.error().str());
  // per-frame: auto exposure metered on every image, also in a video or an --all-cues run.
  const bool perFrame = exposureMode == "per-frame";
  if (perFrame) exposureMode = "auto";

  auto checked = cli.readShow(showPath);
  if (!checked) return kExitBadInput;
  const Show* show = &checked->show;
  const ProfileSet* profiles = &checked->profiles;
  RenderJobOptions options{.camera = camera, .width = static_cast<int>(width), .height = static_cast<int>(height),
                           .quality = *q, .exposureMode = parseExposureMode(exposureMode),
                           .bloom = static_cast<float>(bloom), .mergeCells = cells == "merged", .bodies = !noBodies,
                           .exrPixel = *parseExrPixel(exrPixel), .progress = progress};
  if (!std::isnan(exposure)) options.exposureEv = static_cast<float>(exposure);
  if (!shadows.empty()) options.softShadows = shadows == "soft";
  if (particlesOn && particlesOff) return cli.usage("--particles and --no-particles exclude each other");
  if (particlesOn || particlesOff) options.particles = particlesOn;
  if (!plays.empty()) {
    auto state = playListsAt(*show, *profiles, plays, at < 0 ? 1e9 : at, movement == "real");
    if (!state) return fail(state.error().str());
    auto session = RenderSession::open(*show, options);
    if (!session) return fail(session.error().str());
    (*session)->setHazers(hazersOfPlays(*show, plays, at >= 0));
    const std::string comment = "haze render of " + showPath + ", cue lists " + describeListPlays(plays) +
                                (at >= 0 ? ", " + secondsText(at) + " s after time 0" : ", their fades done");
    const Status s = (*session)->renderToFile(*show, *profiles, *state, out, comment, at < 0 ? 0.0 : at);
    if (!s) return fail(s.error().str());
    return 0;
  }
  const CueList* cueList = show->findCueList(list);
  if (!cueList) return fail(showPath + ": no cue list" + (list.empty() ? "" : " named '" + list + "'"));
  if (cueList->cues.empty()) return fail(showPath + ": cue list '" + cueList->name + "' has no cues");
  if (timecode && std::none_of(cueList->cues.begin(), cueList->cues.end(), [](const Cue& c) { return !c.timecode.empty(); }))
    return fail(showPath + ": cue list '" + cueList->name + "' has no cue with a timecode");

  auto session = RenderSession::open(*show, options);
  if (!session) return fail(session.error().str());
  // A video or an --all-cues run under auto exposure is metered once, on the brightest of its cues
  // (app/exposure_lock.h), so fades and the balance between cues show as they are on stage.
  const auto lockExposure = [&](size_t from, size_t to) -> Status {
    if (perFrame || exposureChoiceFor(*show, options).mode != ExposureMode::Auto) return Ok{};
    auto metered = meterCueList(**session, *show, *profiles, *cueList, from, to);
    if (!metered) return metered.error();
    (*session)->lockMeteredEv(metered->meteredEv);
    // Said where progress is (a terminal, --progress): a script's stderr stays for errors.
    if (progress || Progress::stderrIsTerminal())
      std::fprintf(stderr, "haze render: exposure metered once, on cue %s (the brightest); --exposure-mode per-frame "
                   "meters every image\n", cueList->cues[metered->cue].number.c_str());
    return Ok{};
  };

  if (!video.empty()) {
    VideoJob job{.codec = codec, .out = video, .progress = progress, .caption = caption, .frames = frames,
                 .resume = resume};
    VideoPlan& plan = job.plan;
    plan.list = cueList;
    plan.to = cueList->cues.size() - 1;
    plan.holdS = hold;
    plan.durationS = duration;
    plan.fps = fps;
    plan.realMovement = movement == "real";
    plan.timecodeStart = timecode;
    plan.timecodeRate = rate;
    for (auto [number, index] : {std::pair{&from, &plan.from}, std::pair{&to, &plan.to}}) {
      if (number->empty()) continue;
      auto found = findCue(*cueList, *number);
      if (!found) return fail(showPath + ": " + found.error().message);
      *index = *found;
    }
    if (!timelineFile.empty()) {
      if (!from.empty() || !to.empty()) return cli.usage("--timeline gives the GOs itself: no --from or --to with it");
      auto timeline = readTimeline(timelineFile, *show, *cueList, hold);
      if (!timeline) return fail(timeline.error().str());
      plan.timeline = std::move(*timeline);
    }
    if (plan.from > plan.to)
      return fail("--from " + cueList->cues[plan.from].number + " comes after --to " + cueList->cues[plan.to].number +
                  " in cue list '" + cueList->name + "'");
    const bool wholeList = plan.timeline || plan.timecodeStart;
    if (Status s = lockExposure(wholeList ? 0 : plan.from - (plan.from > 0 ? 1 : 0),
                                wholeList ? cueList->cues.size() - 1 : plan.to);
        !s)
      return fail(s.error().str());
    const auto s = renderVideo(**session, *show, *profiles, job);
    if (!s) return fail(s.error().str());
    std::printf("%s\n", video.c_str());
    // What a farm's task did, for its log: how much of its range it had to draw.
    if (frames || resume)
      std::printf("frames %s: %d, %d drawn, %d repeated, %d complete already\n",
                  frames ? frameRange.c_str() : "all", s->frames, s->drawn, s->frames - s->drawn - s->skipped,
                  s->skipped);
    return 0;
  }

  auto renderCue = [&](size_t index, const std::filesystem::path& file) -> bool {
    const StageState state = at < 0 ? trackedState(*show, *profiles, *cueList, index)
                             : movement == "real" ? movingStateAt(*show, *profiles, *cueList, index, at)
                                                  : stateAt(*show, *profiles, *cueList, index, at);
    if (at < 0)
      (*session)->setHazers(hazerSchedule(*show, {{cueList, index}}, {}));
    else if (index > 0)
      (*session)->setHazers(hazerSchedule(*show, {{cueList, index - 1}}, {{cueList, index, 0.0}}));
    else
      (*session)->setHazers(hazerSchedule(*show, {}, {{cueList, index, 0.0}}));
    const Cue& c = cueList->cues[index];
    const std::string comment = "haze render of " + showPath + ", cue list " + cueList->name + ", cue " + c.number +
                                (c.label.empty() ? "" : " \"" + c.label + "\"") +
                                (at >= 0 ? ", " + secondsText(at) + " s after GO" : ", its full state");
    const Status s = (*session)->renderToFile(*show, *profiles, state, file, comment, at < 0 ? 0.0 : at);
    if (!s) {
      fail(s.error().str());
      return false;
    }
    return true;
  };

  if (timecode) {
    // One copy of the firing rule: a still is the first reading of a timecode, which chases.
    LivePlayback playback(*show, *profiles, cueList);
    playback.timecode(*timecode, rate, 0.0);
    const StageState state = playback.stage(0.0, {}, {});
    const auto current = playback.currentCue();
    if (current) (*session)->setHazers(hazerSchedule(*show, {{cueList, *current}}, {}));
    const std::string where = current ? "cue " + cueList->cues[*current].number : "before the first timed cue";
    std::fprintf(stderr, "haze render: timecode %s: %s\n", timecode->str().c_str(), where.c_str());
    const std::string comment = "haze render of " + showPath + ", cue list " + cueList->name + ", timecode " +
                                timecode->str() + " (" + where + ")";
    const Status s = (*session)->renderToFile(*show, *profiles, state, out, comment, 0.0);
    if (!s) return fail(s.error().str());
    return 0;
  }

  if (allCues) {
    const std::filesystem::path dir(out);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return fail(out + ": cannot create the folder: " + ec.message());
    if (Status s = lockExposure(0, cueList->cues.size() - 1); !s) return fail(s.error().str());
    Progress report("haze render", "cues", static_cast<long>(cueList->cues.size()), progress);
    for (size_t i = 0; i < cueList->cues.size(); ++i) {
      const auto file = dir / ("cue-" + cueList->cues[i].number + ".png");
      if (!renderCue(i, file)) return 1;
      report.step(static_cast<long>(i + 1));
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
