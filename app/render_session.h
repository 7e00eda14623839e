// A headless rendering session for one show: the EGL context, the venue and a renderer, made
// once and reused for every image (all cues of a show share the venue and the shadow caches).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "shows/frame/atmosphere_field.h"
#include "app/render_job.h"
#include "fixtures/core/result.h"
#include "renderer/context.h"
#include "renderer/renderer.h"
#include "shows/scene/venue.h"

namespace haze {

RenderSettings renderSettingsFor(Quality q, int width, int height);
// "draft", "default", "high" or "reference": the name parseQuality reads.
const char* qualityName(Quality q);
Result<Quality> parseQuality(const std::string& name);

// writeExr, with a warning on stderr naming the file when half clamped pixels.
Status writeExrWarning(const ImageRGB& image, const std::filesystem::path& out, const ExrOptions& options);

class RenderSession {
 public:
  static Result<std::unique_ptr<RenderSession>> open(const Show& show, const RenderJobOptions& options);

  // The pieces of renderToFile, for frame loops (videos): draw a state (with the CPU reference
  // under Quality::Reference), then read the radiometric image or the display encoding, metered
  // and exposed exactly as a PNG of renderToFile.
  // reportRows: the CPU reference's rows as a progress line (a still; a video reports frames).
  // clockS: the playback time, for the density field (docs/shows.md, "Density").
  Status draw(const Show& show, const ProfileSet& profiles, const StageState& state, bool reportRows = false,
              double clockS = 0.0);
  ImageRGB radiance() const;
  std::vector<unsigned char> display(const Show& show);
  const RenderJobOptions& options() const { return options_; }
  // How the hazers run over the playback (shows/hazer_levels.h); the frames drawn after this
  // see the density field of that schedule.
  void setHazers(HazerSchedule hazers) { hazers_ = std::move(hazers); }
  // Visible dust for the frames drawn after this (FrameOptions::particles); none: as the show says.
  void setParticles(std::optional<bool> on) { particles_ = on; }
  // Whether draw() draws particles for this show now.
  bool particlesOn(const Show& show) const {
    return particles_.value_or(show.atmosphere.particles && show.atmosphere.particles->enabled);
  }

  // `comment` goes into an EXR's header (what was rendered: show, cue list, cue, time).
  Status renderToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                      const std::filesystem::path& out, const std::string& comment = {}, double clockS = 0.0);
  // The absolute EV of the last PNG (the metered one plus the offset, under auto).
  float lastExposureEv() const { return lastExposureEv_; }
  // Under auto exposure, display() (and PNGs) use this metered EV instead of metering each image:
  // one exposure for a whole video or cue list (app/exposure_lock.h). nullopt: meter each image.
  void lockMeteredEv(std::optional<float> meteredEv) { lockedMeteredEv_ = meteredEv; }
  // What the meter says of the image drawn last, as display() would meter it.
  float meteredEv() { return renderer_->meter().ev; }
  Renderer& renderer() { return *renderer_; }
  const Venue& venue() const { return venue_; }

 private:
  RenderJobOptions options_;
  std::unique_ptr<GlContext> context_;
  Venue venue_;
  std::unique_ptr<Renderer> renderer_;
  float lastExposureEv_ = 0.0f;
  std::optional<float> lockedMeteredEv_;
  std::optional<ImageRGB> referenceImage_;  // the last draw's, under Quality::Reference
  AtmosphereField atmosphere_;
  HazerSchedule hazers_;
  // What draw() passes as FrameOptions::particles (renderToFile turns them off for PFM and EXR).
  std::optional<bool> particles_;
};

}  // namespace haze
