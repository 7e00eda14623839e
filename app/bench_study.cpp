#include "app/bench_study.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "app/bench_scene.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/image_compare.h"

namespace haze {
namespace {

int fail(const std::string& line) {
  std::fprintf(stderr, "haze bench: %s\n", line.c_str());
  return 1;
}

}  // namespace

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The paper's accuracy study redone against the reference: error and time per plane count,
// per lattice size, and for the jittered, fused and accumulated variants (docs/rendering.md).
int runStudy(int width, int height) {
  const Venue venue = studyVenue();
  const FrameState frame = studyFrame();
  const auto t0 = std::chrono::steady_clock::now();
  const ImageRGB ref = renderReference(venue, frame, width, height);
  const double refMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("| variant | planes | mean relative error | ms per frame |\n| --- | --- | --- | --- |\n");
  std::printf("| reference | - | 0 | %.0f |\n", refMs);
  struct Variant {
    std::string name;
    RenderSettings s;
  };
  std::vector<Variant> variants;
  const RenderSettings base{.width = width, .height = height, .lightMapSize = 1024, .shadowMapSize = 2048};
  for (int planes : {15, 30, 75, 150}) {
    RenderSettings s = base;
    s.planes = planes;
    s.fusedPlanes = false;
    s.jitter = false;
    variants.push_back({"planes, per pixel, no jitter", s});
  }
  for (int lattice : {5, 20, 80}) {
    RenderSettings s = base;
    s.planes = 75;
    s.lattice = lattice;
    variants.push_back({"lattice " + std::to_string(lattice) + "x" + std::to_string(lattice), s});
  }
  for (int planes : {15, 30, 75, 150}) {
    RenderSettings s = base;
    s.planes = planes;
    s.fusedPlanes = false;
    s.jitter = true;
    variants.push_back({"planes, jittered", s});
  }
  for (int planes : {15, 30, 75}) {
    RenderSettings s = base;
    s.planes = planes;
    s.fusedPlanes = false;
    s.frames = 8;
    variants.push_back({"planes, jittered, 8 frames accumulated", s});
  }
  for (int planes : {15, 30, 75, 150}) {
    RenderSettings s = base;
    s.planes = planes;
    s.minSamplesPerChord = 0;
    variants.push_back({"fused, jittered", s});
  }
  for (int planes : {15, 48}) {
    RenderSettings s = base;
    s.planes = planes;
    s.minSamplesPerChord = 16;
    variants.push_back({"fused, jittered, 16 samples per chord", s});
  }
  for (const Variant& v : variants) {
    auto r = Renderer::create(venue, v.s);
    if (!r) return fail(r.error().str());
    (*r)->render(frame);  // shadow map and light map made here
    std::vector<double> times;
    for (int i = 0; i < 3; ++i) {
      const auto t1 = std::chrono::steady_clock::now();
      (*r)->render(frame);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count());
    }
    auto c = compareImages((*r)->readRadiance(), ref);
    if (!c) return fail(v.name + ": " + c.error().str());
    std::printf("| %s | %d | %.2f %% | %.1f |\n", v.name.c_str(), v.s.planes, 100.0 * c->meanRelError,
                medianOf(times));
  }
  return 0;
}

}  // namespace haze
