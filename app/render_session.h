// A headless rendering session for one show: the EGL context, the venue and a renderer, made
// once and reused for every image (all cues of a show share the venue and the shadow caches).
#pragma once

#include <filesystem>
#include <memory>

#include "app/render_job.h"
#include "fixtures/core/result.h"
#include "renderer/context.h"
#include "renderer/renderer.h"
#include "renderer/scene/venue.h"

namespace haze {

RenderSettings renderSettingsFor(Quality q, int width, int height);
Result<Quality> parseQuality(const std::string& name);

class RenderSession {
 public:
  static Result<std::unique_ptr<RenderSession>> open(const Show& show, const RenderJobOptions& options);

  Status renderToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                      const std::filesystem::path& out, float exposureEv = 0.0f, float bloom = 0.0f);
  Renderer& renderer() { return *renderer_; }
  const Venue& venue() const { return venue_; }

 private:
  RenderJobOptions options_;
  std::unique_ptr<GlContext> context_;
  Venue venue_;
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace haze
