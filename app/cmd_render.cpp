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
    "--cells auto|separate|merged: a fixture's cells as one beam where they are driven alike and packed\n"
    "close enough to overlap within a metre of it, else one beam per cell (auto, the default); one beam\n"
    "per cell always (separate; auto is separate at --quality reference); the cells that share a\n"
    "light map always as one beam (merged).\n"
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

// What the command line says, as parsed, and what checkOptions derives from it.
struct RenderArgs {
  std::string showPath, cue, list, out, camera, quality = "default", exposureMode, exrPixel = "half", movement = "real",
                                                cells = "auto", shadows;
  double at = -1.0, exposure = std::nan(""), bloom = 0.0;
  int width = 1280, height = 720;
  bool allCues = false, progress = false, caption = false, noBodies = false, particlesOn = false, particlesOff = false;
  std::string video, from, to, codec = "libx264", timelineFile, timecodeText, timecodeRate = "25", frameRange;
  bool resume = false;
  double hold = 2.0, duration = 0.0;
  int fps = 25;
  std::vector<ListPlay> plays;
  std::string playError;
  // Derived by checkOptions.
  std::optional<FrameRange> frames;
  std::optional<Timecode> timecode;
  int rate = 25;
  bool perFrame = false;  // auto exposure metered on every image, also in a video or an --all-cues run
};

void declareOptions(CommandLine& cli, RenderArgs& a) {
  cli.custom("--play", "LIST=CUE[@MASTER][+GO_S]", [&a](const std::string& v) {
    auto p = parseListPlay(v);
    if (!p && a.playError.empty()) a.playError = p.error().message;
    if (p) a.plays.push_back(*p);
    return true;
  });
  cli.text("--cue", a.cue, "a cue number")
      .flag("--all-cues", a.allCues)
      .number("--at", a.at, 0.0, 1e9, "seconds >= 0")
      .text("--list", a.list, "a cue list name")
      .text("--camera", a.camera, "a camera name")
      .integer("--width", a.width, 1, 16384, "a whole number 1..16384")
      .integer("--height", a.height, 1, 16384, "a whole number 1..16384")
      .choice("--quality", a.quality, {"draft", "default", "high", "reference"})
      .number("--exposure", a.exposure, -100, 100, "a number of EV")
      .choice("--exposure-mode", a.exposureMode, {"auto", "manual", "per-frame"})
      .number("--bloom", a.bloom, 0, 1, "a fraction 0..1")
      .choice("--movement", a.movement, {"real", "instant"})
      .choice("--cells", a.cells, cellBeamsNames())
      .choice("--shadows", a.shadows, {"soft", "hard"})
      .choice("--exr-pixel", a.exrPixel, {"half", "float"})
      .text("-o|--output", a.out, "a file or a folder")
      .text("--video", a.video, "a video file (OUT.mp4) or an image sequence (OUT-%05d.png)")
      .text("--from", a.from, "a cue number")
      .text("--to", a.to, "a cue number")
      .integer("--fps", a.fps, 1, 240, "frames per second, 1..240")
      .number("--hold", a.hold, 0, 3600, "seconds 0..3600")
      .number("--duration", a.duration, 0, 86400, "seconds 0..86400")
      .text("--codec", a.codec, "an FFmpeg encoder name")
      .text("--frames", a.frameRange, "frames A-B of the video, from 0")
      .flag("--resume", a.resume)
      .flag("--progress", a.progress)
      .flag("--caption", a.caption)
      .flag("--no-bodies", a.noBodies)
      .flag("--particles", a.particlesOn)
      .flag("--no-particles", a.particlesOff)
      .text("--timeline", a.timelineFile, "a JSON file of GO times")
      .text("--timecode", a.timecodeText, "a timecode hh:mm:ss:ff")
      .choice("--timecode-rate", a.timecodeRate, {"24", "25", "30"})
      .positional(a.showPath, "show");
}

// The options that exclude or need each other; the usage line of the first broken rule, or none.
std::optional<std::string> checkOptions(RenderArgs& a) {
  if (!a.playError.empty()) return "--play " + a.playError;
  const bool still = !a.cue.empty() || a.allCues || a.at >= 0;
  if (!a.plays.empty() && (!a.video.empty() || a.allCues || !a.cue.empty() || !a.list.empty() || !a.timecodeText.empty()))
    return "--play renders one still of the lists it names; expected no --video, --all-cues, --cue, --list or --timecode with it";
  if (!a.video.empty() && (!a.out.empty() || still))
    return "--video renders a cue range (--from, --to): -o, --all-cues, --cue and --at are for stills";
  if (a.video.empty() && (!a.from.empty() || !a.to.empty())) return "--from and --to choose the cues of a --video";
  if (!a.frameRange.empty()) {
    auto parsed = parseFrameRange(a.frameRange);
    if (!parsed) return parsed.error().message;
    a.frames = *parsed;
  }
  if ((a.frames || a.resume) && a.video.empty())
    return "--frames and --resume render part of a --video image sequence (OUT-%05d.png)";
  if (a.out.empty() && a.video.empty())
    return "no output given: -o OUT.png|OUT.pfm|OUT.exr, -o DIR/ with --all-cues, or --video OUT.mp4";
  if (a.allCues && !a.cue.empty()) return "--cue and --all-cues exclude each other";
  a.rate = std::stoi(a.timecodeRate);
  if (!a.timecodeText.empty()) {
    a.timecode = parseTimecode(a.timecodeText);
    if (!a.timecode || a.timecode->frames >= a.rate)
      return "--timecode: expected hh:mm:ss:ff within a day, frames below " + a.timecodeRate + ", got '" + a.timecodeText + "'";
    if (still) return "--timecode chooses the moment itself: no --cue, --all-cues or --at";
    if (!a.from.empty() || !a.to.empty() || !a.timelineFile.empty())
      return "--timecode plays the cues at their timecodes: no --from, --to or --timeline with it";
  }
  if (a.particlesOn && a.particlesOff) return "--particles and --no-particles exclude each other";
  if (!a.timelineFile.empty() && (!a.from.empty() || !a.to.empty()))
    return "--timeline gives the GOs itself: no --from or --to with it";
  a.perFrame = a.exposureMode == "per-frame";
  if (a.perFrame) a.exposureMode = "auto";
  return std::nullopt;
}

RenderJobOptions jobOptions(const RenderArgs& a) {
  RenderJobOptions o{.camera = a.camera, .width = a.width, .height = a.height, .quality = *parseQuality(a.quality),
                     .exposureMode = parseExposureMode(a.exposureMode), .bloom = static_cast<float>(a.bloom),
                     .cells = cellBeamsNamed(a.cells),
                     .bodies = !a.noBodies, .exrPixel = *parseExrPixel(a.exrPixel),
                     .progress = a.progress};
  if (!std::isnan(a.exposure)) o.exposureEv = static_cast<float>(a.exposure);
  if (!a.shadows.empty()) o.softShadows = a.shadows == "soft";
  if (a.particlesOn || a.particlesOff) o.particles = a.particlesOn;
  return o;
}

// One render, from the show read and checked: what every mode below shares.
struct RenderRun {
  const RenderArgs& args;
  const CommandLine& cli;
  const Show& show;
  const ProfileSet& profiles;
  RenderJobOptions options;
  int fail(const std::string& line) const { return cli.fail(line); }
};

// --play: several lists at once, one still.
int renderPlays(const RenderRun& r) {
  const RenderArgs& a = r.args;
  auto state = playListsAt(r.show, r.profiles, a.plays, a.at < 0 ? 1e9 : a.at, a.movement == "real");
  if (!state) return r.fail(state.error().str());
  auto session = RenderSession::open(r.show, r.options);
  if (!session) return r.fail(session.error().str());
  (*session)->setHazers(hazersOfPlays(r.show, a.plays, a.at >= 0));
  const std::string comment = "haze render of " + a.showPath + ", cue lists " + describeListPlays(a.plays) +
                              (a.at >= 0 ? ", " + secondsText(a.at) + " s after time 0" : ", their fades done");
  const Status s = (*session)->renderToFile(r.show, r.profiles, *state, a.out, comment, a.at < 0 ? 0.0 : a.at);
  return s ? 0 : r.fail(s.error().str());
}

// A video or an --all-cues run under auto exposure is metered once, on the brightest of its cues
// (app/exposure_lock.h), so fades and the balance between cues show as they are on stage.
Status lockExposure(const RenderRun& r, RenderSession& session, const CueList& list, size_t from, size_t to) {
  if (r.args.perFrame || exposureChoiceFor(r.show, r.options).mode != ExposureMode::Auto) return Ok{};
  auto metered = meterCueList(session, r.show, r.profiles, list, from, to);
  if (!metered) return metered.error();
  session.lockMeteredEv(metered->meteredEv);
  // Said where progress is (a terminal, --progress): a script's stderr stays for errors.
  if (r.args.progress || Progress::stderrIsTerminal())
    std::fprintf(stderr, "haze render: exposure metered once, on cue %s (the brightest); --exposure-mode per-frame "
                 "meters every image\n", list.cues[metered->cue].number.c_str());
  return Ok{};
}

// --video: the cue range played as on stage (shows/frame/video_timeline.h).
int renderVideoRange(const RenderRun& r, RenderSession& session, const CueList& list) {
  const RenderArgs& a = r.args;
  VideoJob job{.codec = a.codec, .out = a.video, .progress = a.progress, .caption = a.caption, .frames = a.frames,
               .resume = a.resume};
  VideoPlan& plan = job.plan;
  plan.list = &list;
  plan.to = list.cues.size() - 1;
  plan.holdS = a.hold;
  plan.durationS = a.duration;
  plan.fps = a.fps;
  plan.realMovement = a.movement == "real";
  plan.timecodeStart = a.timecode;
  plan.timecodeRate = a.rate;
  for (auto [number, index] : {std::pair{&a.from, &plan.from}, std::pair{&a.to, &plan.to}}) {
    if (number->empty()) continue;
    auto found = findCue(list, *number);
    if (!found) return r.fail(a.showPath + ": " + found.error().message);
    *index = *found;
  }
  if (!a.timelineFile.empty()) {
    auto timeline = readTimeline(a.timelineFile, r.show, list, a.hold);
    if (!timeline) return r.fail(timeline.error().str());
    plan.timeline = std::move(*timeline);
  }
  if (plan.from > plan.to)
    return r.fail("--from " + list.cues[plan.from].number + " comes after --to " + list.cues[plan.to].number +
                  " in cue list '" + list.name + "'");
  const bool wholeList = plan.timeline || plan.timecodeStart;
  if (Status s = lockExposure(r, session, list, wholeList ? 0 : plan.from - (plan.from > 0 ? 1 : 0),
                              wholeList ? list.cues.size() - 1 : plan.to);
      !s)
    return r.fail(s.error().str());
  const auto s = renderVideo(session, r.show, r.profiles, job);
  if (!s) return r.fail(s.error().str());
  std::printf("%s\n", a.video.c_str());
  // What a farm's task did, for its log: how much of its range it had to draw.
  if (a.frames || a.resume)
    std::printf("frames %s: %d, %d drawn, %d repeated, %d complete already\n", a.frames ? a.frameRange.c_str() : "all",
                s->frames, s->drawn, s->frames - s->drawn - s->skipped, s->skipped);
  return 0;
}

// --timecode: one still, the first reading of a timecode (one copy of the firing rule: the
// live engine's, which chases).
int renderTimecodeStill(const RenderRun& r, RenderSession& session, const CueList& list) {
  const RenderArgs& a = r.args;
  LivePlayback playback(r.show, r.profiles, &list);
  playback.timecode(*a.timecode, a.rate, 0.0);
  const StageState state = playback.stage(0.0, {}, {});
  const auto current = playback.currentCue();
  if (current) session.setHazers(hazerSchedule(r.show, {{&list, *current}}, {}));
  const std::string where = current ? "cue " + list.cues[*current].number : "before the first timed cue";
  std::fprintf(stderr, "haze render: timecode %s: %s\n", a.timecode->str().c_str(), where.c_str());
  const std::string comment = "haze render of " + a.showPath + ", cue list " + list.name + ", timecode " +
                              a.timecode->str() + " (" + where + ")";
  const Status s = session.renderToFile(r.show, r.profiles, state, a.out, comment, 0.0);
  return s ? 0 : r.fail(s.error().str());
}

// One cue's still: its full (tracked) state, or --at seconds after its GO.
Status renderCueStill(const RenderRun& r, RenderSession& session, const CueList& list, size_t index,
                      const std::filesystem::path& file) {
  const RenderArgs& a = r.args;
  const StageState state = a.at < 0 ? trackedState(r.show, r.profiles, list, index)
                           : a.movement == "real" ? movingStateAt(r.show, r.profiles, list, index, a.at)
                                                  : stateAt(r.show, r.profiles, list, index, a.at);
  if (a.at < 0)
    session.setHazers(hazerSchedule(r.show, {{&list, index}}, {}));
  else if (index > 0)
    session.setHazers(hazerSchedule(r.show, {{&list, index - 1}}, {{&list, index, 0.0}}));
  else
    session.setHazers(hazerSchedule(r.show, {}, {{&list, index, 0.0}}));
  const Cue& c = list.cues[index];
  const std::string comment = "haze render of " + a.showPath + ", cue list " + list.name + ", cue " + c.number +
                              (c.label.empty() ? "" : " \"" + c.label + "\"") +
                              (a.at >= 0 ? ", " + secondsText(a.at) + " s after GO" : ", its full state");
  return session.renderToFile(r.show, r.profiles, state, file, comment, a.at < 0 ? 0.0 : a.at);
}

// --all-cues: one PNG per cue into a folder, under one metered exposure.
int renderAllCues(const RenderRun& r, RenderSession& session, const CueList& list) {
  const std::filesystem::path dir(r.args.out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return r.fail(r.args.out + ": cannot create the folder: " + ec.message());
  if (Status s = lockExposure(r, session, list, 0, list.cues.size() - 1); !s) return r.fail(s.error().str());
  Progress report("haze render", "cues", static_cast<long>(list.cues.size()), r.args.progress);
  for (size_t i = 0; i < list.cues.size(); ++i) {
    const auto file = dir / ("cue-" + list.cues[i].number + ".png");
    if (Status s = renderCueStill(r, session, list, i, file); !s) return r.fail(s.error().str());
    report.step(static_cast<long>(i + 1));
    std::printf("%s\n", file.string().c_str());
  }
  return 0;
}

// Everything but --play renders from one cue list: a video, a timecode's still, every cue, or one.
int renderFromList(const RenderRun& r) {
  const RenderArgs& a = r.args;
  const CueList* list = r.show.findCueList(a.list);
  if (!list) return r.fail(a.showPath + ": no cue list" + (a.list.empty() ? "" : " named '" + a.list + "'"));
  if (list->cues.empty()) return r.fail(a.showPath + ": cue list '" + list->name + "' has no cues");
  if (a.timecode && std::none_of(list->cues.begin(), list->cues.end(), [](const Cue& c) { return !c.timecode.empty(); }))
    return r.fail(a.showPath + ": cue list '" + list->name + "' has no cue with a timecode");
  auto session = RenderSession::open(r.show, r.options);
  if (!session) return r.fail(session.error().str());
  if (!a.video.empty()) return renderVideoRange(r, **session, *list);
  if (a.timecode) return renderTimecodeStill(r, **session, *list);
  if (a.allCues) return renderAllCues(r, **session, *list);
  size_t index = 0;
  if (!a.cue.empty()) {
    auto found = findCue(*list, a.cue);
    if (!found) return r.fail(found.error().str());
    index = *found;
  }
  const Status s = renderCueStill(r, **session, *list, index, a.out);
  return s ? 0 : r.fail(s.error().str());
}

}  // namespace

int runRender(const Args& args) {
  RenderArgs a;
  CommandLine cli("haze render", kUsage);
  declareOptions(cli, a);
  if (auto done = cli.parse(args)) return *done;
  if (auto wrong = checkOptions(a)) return cli.usage(*wrong);
  auto checked = cli.readShow(a.showPath);
  if (!checked) return kExitBadInput;
  const RenderRun run{.args = a, .cli = cli, .show = checked->show, .profiles = checked->profiles, .options = jobOptions(a)};
  return a.plays.empty() ? renderFromList(run) : renderPlays(run);
}

}  // namespace haze
