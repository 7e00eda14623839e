#include "app/render_video.h"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>

#include <nlohmann/json.hpp>

#include "app/progress.h"
#include "renderer/output/caption.h"
#include "renderer/output/exr.h"
#include "renderer/output/video_writer.h"
#include "renderer/scene/image.h"
#include "shows/cue_player.h"
#include "shows/cue_timeline.h"
#include "shows/dmx/live_playback.h"
#include "shows/hazer_levels.h"
#include "shows/movement.h"

namespace haze {
namespace {

volatile std::sig_atomic_t interrupted = 0;
void onInterrupt(int) { interrupted = 1; }

// Ctrl-C while this lives sets `interrupted` instead of killing the process, so the loop can
// stop between frames and remove its temporary file.
class InterruptGuard {
 public:
  InterruptGuard() {
    interrupted = 0;
    previous_ = std::signal(SIGINT, onInterrupt);
    previousTerm_ = std::signal(SIGTERM, onInterrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_);
    std::signal(SIGTERM, previousTerm_);
  }

 private:
  void (*previous_)(int);
  void (*previousTerm_)(int);
};

const std::regex& framePattern() {
  static const std::regex r("%0?[0-9]*d");
  return r;
}

std::filesystem::path sequenceFile(const std::filesystem::path& pattern, int frame) {
  const std::string name = pattern.filename().string();
  std::smatch m;
  std::regex_search(name, m, framePattern());
  char number[32];
  std::snprintf(number, sizeof number, m.str().c_str(), frame);
  return pattern.parent_path() / (m.prefix().str() + number + m.suffix().str());
}

}  // namespace

bool isImageSequence(const std::filesystem::path& out, std::string& error) {
  const std::string name = out.filename().string();
  if (name.find('%') == std::string::npos) return false;
  const auto count = std::distance(std::sregex_iterator(name.begin(), name.end(), framePattern()), std::sregex_iterator());
  const auto percents = std::count(name.begin(), name.end(), '%');
  const std::string ext = out.extension().string();
  if (count != 1 || percents != 1)
    error = "an image sequence needs one frame number in its name, like OUT-%05d.png";
  else if (ext != ".png" && ext != ".exr")
    error = "an image sequence is .png or .exr (got '" + ext + "')";
  return true;
}

Result<CueTimeline> readTimeline(const std::filesystem::path& file, const Show& show, const CueList& list, double holdS) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{file.string(), "", "cannot open the timeline"};
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto bad = [&](const std::string& where, const std::string& what) { return Error{file.string(), where, what}; };
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return bad("", "not a JSON object");
  if (!doc.contains("go") || !doc["go"].is_array() || doc["go"].empty())
    return bad("/go", "expected a list of GOs: [{\"cue\": \"1\", \"at\": 0}, ...]");
  CueTimeline timeline;
  double last = 0.0;
  for (size_t i = 0; i < doc["go"].size(); ++i) {
    const auto& go = doc["go"][i];
    const std::string at = "/go/" + std::to_string(i);
    if (!go.is_object() || !go.contains("cue") || !go["cue"].is_string())
      return bad(at + "/cue", "expected a cue number as text (\"2\", \"4.5\")");
    if (!go.contains("at") || !go["at"].is_number() || go["at"].get<double>() < last)
      return bad(at + "/at", i == 0 ? "expected seconds >= 0" : "expected seconds, not before the GO before it");
    auto cue = findCue(list, go["cue"].get<std::string>());
    if (!cue) return bad(at + "/cue", cue.error().message);
    last = go["at"].get<double>();
    timeline.gos.push_back({.cueIndex = *cue, .atS = last});
    const Cue& c = list.cues[*cue];
    timeline.endS = std::max(timeline.endS, last + cueDurationS(show, c) + holdS);
  }
  if (doc.contains("end")) {
    if (!doc["end"].is_number() || doc["end"].get<double>() <= 0) return bad("/end", "expected seconds > 0");
    timeline.endS = doc["end"].get<double>();
  }
  return timeline;
}

Result<VideoStats> renderVideo(RenderSession& session, const Show& show, const ProfileSet& profiles, const VideoJob& job) {
  const CueList& list = *job.list;
  const CueTimeline timeline = job.timeline ? *job.timeline : playCueRange(show, list, job.from, job.to, job.holdS);
  const size_t firstCue = timeline.gos.empty() ? job.from : timeline.gos.front().cueIndex;
  std::optional<LivePlayback> live;
  long startFrame = 0;
  double lastTimedEndS = 0.0;  // seconds after the start
  if (job.timecodeStart) {
    live.emplace(show, profiles, &list);
    startFrame = job.timecodeStart->toFrames(job.timecodeRate);
    for (const Cue& c : list.cues)
      if (auto t = parseTimecode(c.timecode))
        lastTimedEndS = std::max(lastTimedEndS, static_cast<double>(t->toFrames(job.timecodeRate) - startFrame) /
                                                        job.timecodeRate + cueDurationS(show, c));
  }
  const double endS = job.durationS > 0 ? job.durationS : live ? lastTimedEndS + job.holdS : timeline.endS;
  const int frames = std::max(1, static_cast<int>(std::ceil(endS * job.fps - 1e-9)));
  const RenderJobOptions& options = session.options();

  std::string patternError;
  const bool sequence = isImageSequence(job.out, patternError);
  if (!patternError.empty()) return Error{job.out.string(), "", patternError};
  const bool exr = sequence && job.out.extension() == ".exr";
  // EXR frames are radiometric: no display particles unless --particles asked for them.
  if (exr && !options.particles) session.setParticles(false);
  if (exr && options.particles && *options.particles)
    std::fprintf(stderr, "haze: note: %s: --particles adds visible dust on top of the radiance; its pixels are the "
                 "radiometric image plus the particles' display light (docs/rendering.md, \"Particles\")\n",
                 job.out.string().c_str());
  // Particles drift with the air: every frame differs while they are drawn.
  const bool particlesMove = session.particlesOn(show);
  std::unique_ptr<VideoWriter> writer;
  if (!sequence) {
    auto created = VideoWriter::create(job.out, {.width = options.width, .height = options.height, .fps = job.fps,
                                                 .codec = job.codec,
                                                 .title = show.file.filename().string() + ", cue list " + list.name});
    if (!created) return created.error();
    writer = std::move(*created);
  }

  // The hazers go with the same GOs as the fixtures (docs/shows.md, "Hazers in cues").
  std::vector<HazerCue> hazersOnStage, hazerGos;
  if (live) {
    // The timecode's own firing rule, played once without drawing: one copy of it.
    LivePlayback dry(show, profiles, &list);
    std::optional<size_t> current;
    for (int f = 0; f < frames; ++f) {
      const double t = static_cast<double>(f) / job.fps;
      const auto label = Timecode::fromFrames(startFrame + static_cast<long>(std::floor(t * job.timecodeRate + 1e-9)),
                                              job.timecodeRate);
      if (!label) break;  // the frame loop says so
      dry.timecode(*label, job.timecodeRate, t);
      const auto now = dry.currentCue();
      if (now && now != current) (f == 0 ? hazersOnStage : hazerGos).push_back({&list, *now, t});
      current = now;
    }
  } else {
    if (firstCue > 0) hazersOnStage.push_back({&list, firstCue - 1, 0.0});
    for (const CueGo& g : timeline.gos) hazerGos.push_back({&list, g.cueIndex, g.atS});
  }
  session.setHazers(hazerSchedule(show, hazersOnStage, hazerGos));

  CuePlayer player(show, profiles, list);
  if (firstCue > 0) player.jumpTo(firstCue - 1, 0.0);
  size_t nextGo = 0;
  StageState lastState;
  MovementFollower heads(show, profiles);  // the command between frames is interpolated
  std::vector<unsigned char> rgb;
  ImageRGB radiance;
  int drawn = 0;
  InterruptGuard guard;
  Progress progress("haze render", "frames", frames, job.progress);
  for (int f = 0; f < frames; ++f) {
    if (interrupted) {
      progress.finish();
      return Error{job.out.string(), "",
                   "interrupted at frame " + std::to_string(f) + " of " + std::to_string(frames) +
                       (sequence ? " (the frames before it are written)" : "; no video written")};
    }
    const double t = static_cast<double>(f) / job.fps;
    StageState state;
    if (live) {
      const long count = startFrame + static_cast<long>(std::floor(t * job.timecodeRate + 1e-9));
      const auto label = Timecode::fromFrames(count, job.timecodeRate);
      if (!label) {
        progress.finish();
        return Error{job.out.string(), "", "timecode passes 24:00:00:00 at frame " + std::to_string(f) +
                                               "; use a shorter --duration"};
      }
      if (const std::string fired = live->timecode(*label, job.timecodeRate, t); !fired.empty())
        std::fprintf(stderr, "haze render: timecode %s: %s\n", label->str().c_str(), fired.c_str());
      state = live->stage(t, {}, {});
    } else {
      for (; nextGo < timeline.gos.size() && timeline.gos[nextGo].atS <= t; ++nextGo)
        if (!timeline.gos[nextGo].byFollow) player.gotoCue(timeline.gos[nextGo].cueIndex, timeline.gos[nextGo].atS);
      state = player.state(t);
    }
    const auto current = live ? live->currentCue() : player.currentCue();
    // Frames of a hold (or of a delay) show an unchanged stage: the frame state is built from
    // the stage state alone, so the last picture is that frame exactly and is not drawn again.
    if (job.realMovement) {
      if (f == 0) heads.reset(state, t);
      state = heads.advance(state, t, true);
    }
    // A drifting density field changes every frame, whatever the stage does.
    if (f == 0 || state != lastState || densityMoves(show.atmosphere) || particlesMove) {
      if (Status s = session.draw(show, profiles, state, false, t); !s) return s.error();
      if (exr)
        radiance = session.radiance();
      else
        rgb = session.display(show);
      lastState = std::move(state);
      ++drawn;
    }
    std::vector<unsigned char> shown;
    if (!exr && job.caption) {
      shown = rgb;
      char text[256];
      const Cue& cue = list.cues[current.value_or(job.from)];
      std::snprintf(text, sizeof text, "cue %s%s%s   %.2f s", cue.number.c_str(), cue.label.empty() ? "" : "  ",
                    cue.label.c_str(), t);
      burnCaption(shown, options.width, options.height, text);
    }
    const std::vector<unsigned char>& frame = job.caption ? shown : rgb;
    if (exr) {
      const Cue& cue = list.cues[current.value_or(job.from)];
      char comment[256];
      std::snprintf(comment, sizeof comment, "haze render --video of %s, cue list %s, frame %d at %.3f s, cue %s",
                    show.file.filename().string().c_str(), list.name.c_str(), f, t, cue.number.c_str());
      if (Status s = writeExrWarning(radiance, sequenceFile(job.out, f),
                                     {.pixel = options.exrPixel, .comment = comment});
          !s)
        return s.error();
    } else if (sequence) {
      if (Status s = writePng8(frame, options.width, options.height, sequenceFile(job.out, f)); !s) return s.error();
    } else if (Status s = writer->addFrame(frame); !s) {
      return s.error();
    }
    progress.step(f + 1);
  }
  progress.finish();
  if (writer)
    if (Status s = writer->finish(); !s) return s.error();
  return VideoStats{.frames = frames, .drawn = drawn};
}

}  // namespace haze
