#include "app/render_session.h"

#include <cstdio>
#include <cstdlib>

#include "shows/frame/frame_builder.h"
#include "app/progress.h"
#include "renderer/reference/reference.h"
#include "shows/scene/image.h"

namespace haze {

RenderSettings renderSettingsFor(Quality q, int width, int height) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  switch (q) {
    case Quality::Draft:
      s = {.width = width, .height = height, .lightMapSize = 256, .shadowMapSize = 512, .planes = 24,
           .scatterDivisor = 2, .frames = 1, .minSamplesPerChord = 4, .sunMapSize = 1024, .sunSteps = 32};
      break;
    case Quality::Default:
      // From HD up the in-scattering is rendered at half resolution and upsampled with the
      // depth, and the pixels where it has detail the upsample cannot rebuild (a gobo near the
      // lens, hard edges) again at full resolution: a quarter of the plane fragments plus a
      // few percent, within 8 % of the reference even for a gobo seen from the side
      // (tests/render/beams_vs_reference_test.cpp, docs/rendering.md, "Refinement").
      s = {.width = width, .height = height, .lightMapSize = 512, .shadowMapSize = 1024, .planes = 48,
           .scatterDivisor = width >= 1280 ? 2 : 1, .refineCurvature = 0.1f, .refineFloor = 2.0f, .frames = 1,
           .minSamplesPerChord = 16, .sunMapSize = 2048, .sunSteps = 96};
      break;
    case Quality::High:
    case Quality::Reference:
      // More planes, finer maps and jittered frames averaged; from HD up the in-scattering at
      // half resolution with the refinement, as default, and three frames, not four: at full
      // resolution the four cost 16 times default's planes pass on the Capture rig (30 times
      // the frame in all) for a picture no different to the eye (docs/rendering.md, "Presets").
      s = {.width = width, .height = height, .lightMapSize = 1024, .shadowMapSize = 2048, .planes = 128,
           .scatterDivisor = width >= 1280 ? 2 : 1, .refineCurvature = 0.1f, .refineFloor = 2.0f,
           .frames = width >= 1280 ? 3 : 4, .minSamplesPerChord = 16, .sunMapSize = 4096, .sunSteps = 128};
      s.shadowTexelBudget = int64_t{64} << 20;  // 256 MB: eight 2048 px maps, 76 of 928 px
      break;
  }
  return s;
}

const char* qualityName(Quality q) {
  switch (q) {
    case Quality::Draft: return "draft";
    case Quality::Default: return "default";
    case Quality::High: return "high";
    case Quality::Reference: return "reference";
  }
  return "default";
}

Result<Quality> parseQuality(const std::string& name) {
  if (name == "draft") return Quality::Draft;
  if (name == "default") return Quality::Default;
  if (name == "high") return Quality::High;
  if (name == "reference") return Quality::Reference;
  return Error{"", "--quality", "unknown quality '" + name + "' (expected draft, default, high or reference)"};
}

Result<std::unique_ptr<RenderSession>> RenderSession::open(const Show& show, const RenderJobOptions& options) {
  auto session = std::unique_ptr<RenderSession>(new RenderSession());
  session->options_ = options;
#ifdef NDEBUG
  const bool debug = std::getenv("HAZE_GL_DEBUG") != nullptr;
#else
  const bool debug = true;  // debug builds always report GL errors (KHR_debug)
#endif
  auto context = createHeadlessContext({.debug = debug});
  if (!context) return context.error();
  session->context_ = std::move(*context);
  if (show.venueGltf.empty()) return Error{show.file.string(), "/venue/gltf", "the show names no venue"};
  auto venue = loadVenue(show.resolve(show.venueGltf));
  if (!venue) return venue.error();
  session->venue_ = std::move(*venue);
  // With --quality reference the CPU makes the image; the GPU renderer only encodes it.
  const Quality gpuQuality = options.quality == Quality::Reference ? Quality::Draft : options.quality;
  auto renderer = Renderer::create(session->venue_, renderSettingsFor(gpuQuality, options.width, options.height));
  if (!renderer) return renderer.error();
  session->renderer_ = std::move(*renderer);
  session->particles_ = options.particles;
  return session;
}

Status RenderSession::draw(const Show& show, const ProfileSet& profiles, const StageState& state, bool reportRows,
                           double clockS) {
  std::vector<std::string> warnings;
  auto density = atmosphere_.at(show, venue_.boundsMin, venue_.boundsMax, clockS, warnings, hazers_);
  for (const std::string& w : warnings) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
  auto frame = buildFrame(show, profiles, state, options_.camera,
                          // The reference integrator draws what is there: every cell (docs/cells.md, "Cost").
                          FrameOptions{.cells = options_.quality == Quality::Reference && options_.cells == CellBeams::Auto
                                                    ? CellBeams::Separate
                                                    : options_.cells,
                                       .bodies = options_.bodies,
                                       .clockS = clockS,
                                       .density = std::move(density),
                                       .softShadows = options_.softShadows,
                                       .particles = particles_});
  if (!frame) return frame.error();
  referenceImage_.reset();
  if (options_.quality == Quality::Reference) {
    // The CPU reference integrator (renderer/reference), the oracle of the accuracy tests;
    // its image goes through the GPU's display encoding.
    Progress progress("haze render (reference)", "rows", options_.height, options_.progress);
    ReferenceOptions reference;
    if (reportRows) reference.onRows = [&progress](int done, int) { progress.step(done); };
    referenceImage_ = renderReference(venue_, *frame, options_.width, options_.height, reference);
    if (reportRows) progress.step(options_.height);  // the last row may have been another thread's
    renderer_->setRadiance(*referenceImage_);
  } else {
    renderer_->render(*frame);
    for (const std::string& w : renderer_->warnings()) std::fprintf(stderr, "haze: warning: %s\n", w.c_str());
  }
  return Ok{};
}

ImageRGB RenderSession::radiance() const { return referenceImage_ ? *referenceImage_ : renderer_->readRadiance(); }

std::vector<unsigned char> RenderSession::display(const Show& show) {
  const ExposureChoice choice = exposureChoiceFor(show, options_);
  const float metered = choice.mode != ExposureMode::Auto ? 0.0f
                       : lockedMeteredEv_                 ? *lockedMeteredEv_
                                                          : renderer_->meter().ev;
  lastExposureEv_ = exposureEvFor(choice, metered);
  return renderer_->readDisplay({.exposureEv = lastExposureEv_, .bloom = options_.bloom});
}

Status RenderSession::renderToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                                   const std::filesystem::path& out, const std::string& comment, double clockS) {
  const std::string ext = out.extension().string();
  if (ext != ".pfm" && ext != ".png" && ext != ".exr")
    return Error{out.string(), "", "unknown image type (expected .png, .pfm or .exr)"};
  // A radiometric file has no display particles unless they were asked for by name.
  particles_ = options_.particles;
  if (ext != ".png" && !particles_) particles_ = false;
  if (ext != ".png" && *particles_)
    std::fprintf(stderr, "haze: note: %s: --particles adds visible dust on top of the radiance; its pixels are "
                 "the radiometric image plus the particles' display light (docs/rendering.md, \"Particles\")\n",
                 out.string().c_str());
  const Status drawn = draw(show, profiles, state, true, clockS);
  particles_ = options_.particles;
  if (!drawn) return drawn;
  if (ext == ".png") return writePng8(display(show), options_.width, options_.height, out);
  if (ext == ".pfm") return writePfm(radiance(), out);
  return writeExrWarning(radiance(), out, {.pixel = options_.exrPixel, .comment = comment});
}

Status writeExrWarning(const ImageRGB& image, const std::filesystem::path& out, const ExrOptions& options) {
  auto written = writeExr(image, out, options);
  if (!written) return written.error();
  if (written->clampedPixels > 0)
    std::fprintf(stderr, "haze: warning: %s: %zu pixels brighter than half's largest value (65504 cd/m^2) "
                 "were clamped to it; --exr-pixel float keeps them\n", out.string().c_str(), written->clampedPixels);
  return Ok{};
}

ExposureChoice exposureChoiceFor(const Show& show, const RenderJobOptions& options) {
  const CameraDef* camera = show.cameras.empty() ? nullptr : &show.cameras.front();
  if (!options.camera.empty()) {
    camera = nullptr;
    for (const CameraDef& c : show.cameras)
      if (c.name == options.camera) camera = &c;
  }
  ExposureChoice choice;
  if (camera && camera->exposure) {
    choice.mode = camera->exposure->manual ? ExposureMode::Manual : ExposureMode::Auto;
    choice.ev = camera->exposure->ev;
  }
  if (options.exposureMode && *options.exposureMode != choice.mode) choice = {.mode = *options.exposureMode, .ev = 0.0f};
  if (options.exposureEv) choice.ev = *options.exposureEv;
  return choice;
}

std::optional<ExposureMode> parseExposureMode(const std::string& name) {
  if (name == "auto") return ExposureMode::Auto;
  if (name == "manual") return ExposureMode::Manual;
  return std::nullopt;
}

Status renderStateToFile(const Show& show, const ProfileSet& profiles, const StageState& state,
                         const RenderJobOptions& options, const std::filesystem::path& out) {
  auto session = RenderSession::open(show, options);
  if (!session) return session.error();
  return (*session)->renderToFile(show, profiles, state, out);
}

}  // namespace haze
