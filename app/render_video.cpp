#include "app/render_video.h"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>

#include "app/progress.h"
#include "renderer/output/caption.h"
#include "renderer/output/exr.h"
#include "renderer/output/frame_files.h"
#include "renderer/output/video_writer.h"
#include "shows/scene/image.h"

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

}  // namespace

Result<VideoStats> renderVideo(RenderSession& session, const Show& show, const ProfileSet& profiles, const VideoJob& job) {
  const CueList& list = *job.plan.list;
  VideoTimeline timeline(show, profiles, job.plan);
  const int frames = timeline.frames();
  const RenderJobOptions& options = session.options();

  std::string patternError;
  const bool sequence = isImageSequence(job.out, patternError);
  if (!patternError.empty()) return Error{job.out.string(), "", patternError};
  if ((job.frames || job.resume) && !sequence)
    return Error{job.out.string(), "", "--frames and --resume write part of an image sequence (OUT-%05d.png or .exr)"};
  const FrameRange range = job.frames.value_or(FrameRange{0, frames - 1});
  if (range.last >= frames)
    return Error{job.out.string(), "", "--frames " + std::to_string(range.first) + "-" + std::to_string(range.last) +
                                           ": this video has " + std::to_string(frames) + " frames (0-" +
                                           std::to_string(frames - 1) + ")"};
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
    auto created = VideoWriter::create(job.out, {.width = options.width, .height = options.height, .fps = job.plan.fps,
                                                 .codec = job.codec,
                                                 .title = show.file.filename().string() + ", cue list " + list.name});
    if (!created) return created.error();
    writer = std::move(*created);
  }

  session.setHazers(timeline.hazers());

  StageState lastState;
  bool havePicture = false;  // whether rgb or radiance holds lastState's picture
  std::vector<unsigned char> rgb;
  ImageRGB radiance;
  int drawn = 0, skipped = 0;
  InterruptGuard guard;
  Progress progress("haze render", "frames", range.count(), job.progress);
  // Every frame before the range is played but not drawn: the heads' travel, the effects and the
  // timecode's firings are stepped from frame 0 (cheap, no GL), so frame A is the stage a whole
  // run shows at A. The density field and the renderer keep nothing from one draw to the next
  // that changes a picture (the field is simulated from 0 to the frame's time in fixed steps, the
  // maps are cached by content), so a range's first draw equals the whole run's draw of it.
  for (int f = 0; f <= range.last; ++f) {
    if (interrupted) {
      progress.finish();
      return Error{job.out.string(), "",
                   "interrupted at frame " + std::to_string(f) + " of " + std::to_string(frames) +
                       (sequence ? " (the frames before it are written)" : "; no video written")};
    }
    auto played = timeline.next();
    if (!played) {
      progress.finish();
      return Error{job.out.string(), "", played.error().message};
    }
    if (f < range.first) continue;
    const std::filesystem::path file = sequence ? sequenceFile(job.out, f) : std::filesystem::path();
    if (job.resume && frameFileComplete(file)) {
      // Written by an earlier run; the next frame drawn cannot reuse a picture this run never made.
      havePicture = false;
      ++skipped;
      progress.step(f - range.first + 1);
      continue;
    }
    if (!played->fired.empty())
      std::fprintf(stderr, "haze render: timecode %s: %s\n", played->timecode->str().c_str(), played->fired.c_str());
    const double t = played->timeS;
    StageState& state = played->state;
    const auto current = played->cue;
    // Frames of a hold (or of a delay) show an unchanged stage: the frame state is built from
    // the stage state alone, so the last picture is that frame exactly and is not drawn again.
    // A drifting density field changes every frame, whatever the stage does.
    if (!havePicture || state != lastState || densityMoves(show.atmosphere) || particlesMove) {
      if (Status s = session.draw(show, profiles, state, false, t); !s) return s.error();
      if (exr)
        radiance = session.radiance();
      else
        rgb = session.display(show);
      lastState = std::move(state);
      havePicture = true;
      ++drawn;
    }
    std::vector<unsigned char> shown;
    if (!exr && job.caption) {
      shown = rgb;
      char text[256];
      const Cue& cue = list.cues[current.value_or(job.plan.from)];
      std::snprintf(text, sizeof text, "cue %s%s%s   %.2f s", cue.number.c_str(), cue.label.empty() ? "" : "  ",
                    cue.label.c_str(), t);
      burnCaption(shown, options.width, options.height, text);
    }
    const std::vector<unsigned char>& frame = job.caption ? shown : rgb;
    if (exr) {
      const Cue& cue = list.cues[current.value_or(job.plan.from)];
      char comment[256];
      std::snprintf(comment, sizeof comment, "haze render --video of %s, cue list %s, frame %d at %.3f s, cue %s",
                    show.file.filename().string().c_str(), list.name.c_str(), f, t, cue.number.c_str());
      if (Status s = writeExrWarning(radiance, file,
                                     {.pixel = options.exrPixel, .comment = comment});
          !s)
        return s.error();
    } else if (sequence) {
      if (Status s = writePng8(frame, options.width, options.height, file); !s) return s.error();
    } else if (Status s = writer->addFrame(frame); !s) {
      return s.error();
    }
    progress.step(f - range.first + 1);
  }
  progress.finish();
  if (writer)
    if (Status s = writer->finish(); !s) return s.error();
  return VideoStats{.frames = range.count(), .drawn = drawn, .skipped = skipped};
}

}  // namespace haze
