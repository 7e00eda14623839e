// haze bench [--fixtures N | --show SHOW [--cue N] [--camera NAME]] [--width W --height H] [--quality Q]
//            [--frames K] [--move DEG [--map-budget MS]] [--compare-reference] --json
//            [--planes N] [--scatter-divisor D] [--min-samples M] (override the preset's values)
// Renders the bench scene (app/bench_scene.*) or a show's cue headless and reports the median
// time per frame and per pass, with shadow and light maps cached after the first (cold) frame,
// as while a designer looks at a cue; the cold frame is reported apart.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "app/bench_scene.h"
#include "app/bench_show.h"
#include "atmosphere/density_sim.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/frame_builder.h"
#include "app/render_session.h"
#include "shows/playback.h"
#include "shows/show.h"
#include "renderer/context.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "renderer/scene/image_compare.h"
#include "renderer/scene/physics.h"

namespace haze {
namespace {

int fail(const std::string& line) {
  std::fprintf(stderr, "haze bench: %s\n", line.c_str());
  return 1;
}

// CPU time of the whole process (llvmpipe's render threads included): on a shared, busy machine
// this moves far less than the wall clock when other jobs take the cores.
double processCpuMs() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

// The process's peak resident memory so far, in MB (what `/usr/bin/time -f %M` reports).
double peakMemoryMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

double median(std::vector<double> v) {
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
                median(times));
  }
  return 0;
}

}  // namespace

constexpr const char* kBenchUsage =
    "usage: haze bench [--fixtures N | --show SHOW [--cue N] [--camera NAME] [--cells separate|merged]]\n"
    "                  [--width W --height H] [--quality Q] [--frames K] [--planes N] [--scatter-divisor D]\n"
    "                  [--min-samples M] [--refine C] [--density N] [--no-bodies | --compare-bodies] [--sun]\n"
    "                  [--shadows soft|hard|compare] [--compare-particles [--particle-density N]]\n"
    "                  [--move DEG [--map-budget MS]] [--compare-reference] [--json]\n"
    "       haze bench --study [--width W --height H]\n"
    "Times the synthetic stage (N fixtures, 16 by default; the stage grows with N) or a show's cue (the\n"
    "first unless --cue, from the show's first camera unless --camera) per frame and per pass;\n"
    "--cells merged draws a fixture's alike cells as one beam (docs/cells.md);\n"
    "--compare-reference also renders the CPU reference and gives the mean relative error; --study runs\n"
    "the virtual-plane accuracy study. --density N also renders the frame through an N^3 density field\n"
    "with a hazer (the bench scene's: docs/rendering.md, \"Density\"), alternating frame by frame with the\n"
    "uniform medium, and gives the cost ratio. --no-bodies leaves the fixtures' housings out;\n"
    "--compare-bodies also renders the frame without them and with every body mesh drawn whole (no\n"
    "culling), alternating frame by frame, and gives the bodies' share of the frame both ways and their\n"
    "cold frames (docs/rendering.md, \"Fixture bodies\"). --shadows soft|hard sets the\n"
    "shadows (default: the show's, soft for the synthetic stage); --shadows compare renders soft and hard\n"
    "alternating frame by frame and gives the soft shadows' cost ratio (docs/rendering.md, \"Soft shadows\").\n"
    "--sun also renders the frame with a sun (azimuth 250, elevation 35, 50000 lux; a show's own sun is left\n"
    "out of the base frame), alternating frame by frame, and gives its cost ratio (docs/rendering.md, \"The sun\").\n"
    "--compare-particles renders it with visible dust too (--particle-density N per m^3), alternating, and\n"
    "gives the cost ratio.\n"
    "--move DEG turns every beam by DEG more about its lens each frame (a pan sweep: every shadow map is out\n"
    "of date each frame) and gives the frames' median and longest times; --map-budget MS spreads the maps'\n"
    "redraws over frames as the GUI does (docs/rendering.md, \"Map work spread over frames\").\n";

int runBench(const Args& args) {
  int fixtures = -1, width = 1280, height = 720, frames = 5;
  std::string quality = "default", showPath, cue, camera, cells = "separate", shadows;
  bool json = false, compare = false, study = false, noBodies = false, compareBodies = false, sun = false,
       compareParticles = false;
  double particleDensity = ParticleSettings{}.densityPerM3;
  int planes = 0, divisor = 0, minSamples = -1;  // 0 / -1: the preset's
  double refine = -1.0;                            // -1: the preset's
  int densityCells = 0;
  double moveDeg = 0.0, mapBudgetMs = 0.0;
  CommandLine cli("haze bench", kBenchUsage);
  cli.integer("--fixtures", fixtures, 0, 4096, "0..4096")
      .text("--show", showPath, "a show file")
      .text("--cue", cue, "a cue number")
      .text("--camera", camera, "a camera name")
      .integer("--width", width, 1, 16384, "1..16384")
      .integer("--height", height, 1, 16384, "1..16384")
      .integer("--frames", frames, 1, 1000, "1..1000")
      .choice("--quality", quality, {"draft", "default", "high", "reference"})
      .flag("--json", json)
      .flag("--compare-reference", compare)
      .flag("--no-bodies", noBodies)
      .flag("--compare-bodies", compareBodies)
      .flag("--sun", sun)
      .flag("--compare-particles", compareParticles)
      .number("--particle-density", particleDensity, 0.0, kMaxParticleDensityPerM3, "particles per m^3, 0..5000")
      .flag("--study", study)
      .integer("--planes", planes, 1, 4096, "1..4096")
      .integer("--scatter-divisor", divisor, 1, 8, "1..8")
      .integer("--min-samples", minSamples, 0, 256, "0..256")
      .number("--refine", refine, 0.0, 2.0, "0..2 (0 = no refinement)")
      .integer("--density", densityCells, 2, kMaxDensityCellsPerSide, "2..256 cells per side")
      .choice("--cells", cells, {"separate", "merged"})
      .choice("--shadows", shadows, {"soft", "hard", "compare"})
      .number("--move", moveDeg, 0.0, 90.0, "0..90 degrees per frame")
      .number("--map-budget", mapBudgetMs, 0.0, 1e6, "milliseconds, 0 = unlimited");
  if (auto done = cli.parse(args)) return *done;
  auto q = parseQuality(quality);
  if (!q) return fail(q.error().str());
  if (*q == Quality::Reference)
    return cli.usage("--quality reference is the CPU integrator: time it against a GPU preset with --compare-reference");
  if (!showPath.empty() && fixtures >= 0) return cli.usage("--fixtures and --show exclude each other");
  if (showPath.empty() && (!cue.empty() || !camera.empty())) return cli.usage("--cue and --camera need --show");
  if (showPath.empty() && cells != "separate") return cli.usage("--cells needs --show");
  auto ctx = createHeadlessContext();
  if (!ctx) return fail(ctx.error().str());
  if (study) return runStudy(width, height);
  Venue venue;
  FrameState frame;
  if (showPath.empty()) {
    fixtures = fixtures < 0 ? 16 : fixtures;
    venue = benchVenue(fixtures);
    frame = benchFrame(fixtures);
    frame.softShadows = true;  // as a show has them unless it asks for hard ones
  } else {
    auto checked = cli.readShow(showPath);
    if (!checked) return kExitBadInput;
    if (Status s = loadBenchShow(checked->show, checked->profiles, cue, camera, cells == "merged", venue, frame, fixtures);
        !s)
      return fail(s.error().str());
  }
  if (noBodies && compareBodies) return cli.usage("--no-bodies and --compare-bodies exclude each other");
  if (compareBodies && densityCells > 0) return cli.usage("--compare-bodies and --density exclude each other");
  const bool compareShadows = shadows == "compare";
  if (compareShadows && (compareBodies || densityCells > 0 || sun || compareParticles))
    return cli.usage("--shadows compare excludes --compare-bodies, --density, --sun and --compare-particles");
  if (!shadows.empty()) frame.softShadows = shadows != "hard";
  if (sun && (compareBodies || densityCells > 0 || compareParticles))
    return cli.usage("--sun excludes --density, --compare-bodies and --compare-particles");
  if (compareParticles && (compareBodies || densityCells > 0))
    return cli.usage("--compare-particles excludes --compare-bodies and --density");
  if (mapBudgetMs > 0.0 && moveDeg <= 0.0) return cli.usage("--map-budget needs --move");
  if (moveDeg > 0.0 && (compareBodies || densityCells > 0 || sun || compareParticles || compareShadows))
    return cli.usage("--move excludes --density, --compare-bodies, --sun, --compare-particles and --shadows compare");
  if (noBodies) {  // the fixtures' housings left out, as haze render --no-bodies does
    frame.bodies.clear();
    frame.bodyMeshes.clear();
  }
  RenderSettings settings = renderSettingsFor(*q, width, height);
  settings.timePasses = true;
  if (planes > 0) settings.planes = planes;
  if (divisor > 0) settings.scatterDivisor = divisor;
  if (minSamples >= 0) settings.minSamplesPerChord = minSamples;
  if (refine >= 0.0) settings.refineCurvature = static_cast<float>(refine);
  settings.mapWorkBudgetMs = mapBudgetMs;
  auto renderer = Renderer::create(venue, settings);
  if (!renderer) return fail(renderer.error().str());
  // The same frame through a density field, on a renderer of its own, alternating with the
  // uniform one so that both see the same load.
  std::unique_ptr<Renderer> dense;
  FrameState denseFrame;
  if (densityCells > 0) {
    DensitySpec spec = benchDensity(densityCells);
    DensitySim sim(spec, densityGrid(spec, venue.boundsMin, venue.boundsMax));
    denseFrame = frame;
    denseFrame.medium.density = std::make_shared<DensityField>(sim.fieldAt(spec.warmupS));
    auto r = Renderer::create(venue, settings);
    if (!r) return fail(r.error().str());
    dense = std::move(*r);
  }
  // The same frame without bodies, the same way: what the bodies cost; and with them drawn
  // whole (RenderSettings::cullBodies off): what the culling saves.
  std::unique_ptr<Renderer> unculled;
  if (compareBodies) {
    denseFrame = frame;
    denseFrame.bodies.clear();
    denseFrame.bodyMeshes.clear();
    auto r = Renderer::create(venue, settings);
    if (!r) return fail(r.error().str());
    dense = std::move(*r);
    RenderSettings whole = settings;
    whole.cullBodies = false;
    auto u = Renderer::create(venue, whole);
    if (!u) return fail(u.error().str());
    unculled = std::move(*u);
  }
  // The same frame with hard shadows, with a sun or with visible dust, the same way: what the
  // soft shadows cost, what the sun costs (its shadow map, its term in the surfaces and its
  // march; the base frame then has none), or what the particles cost (docs/rendering.md).
  if (compareShadows || sun || compareParticles) {
    if (sun) frame.sun = SunState{};
    denseFrame = frame;
    if (compareShadows) denseFrame.softShadows = false;
    if (sun) denseFrame.sun = SunState{.on = true, .direction = sunDirection(250.0f, 35.0f), .illuminance = glm::vec3(50000.0f)};
    if (compareParticles) {
      denseFrame.particles.settings.enabled = true;
      denseFrame.particles.settings.densityPerM3 = static_cast<float>(particleDensity);
    }
    auto r = Renderer::create(venue, settings);
    if (!r) return fail(r.error().str());
    dense = std::move(*r);
  }
  std::vector<double> denseTotal, denseCpu, denseBeams, denseSurfaces, denseParticles, denseGenerate;
  std::vector<double> unculledTotal, unculledSurfaces;
  int bodyMeshesDrawn = 0;
  double denseColdMs = 0.0;

  std::vector<double> total, cpu, shadow, surfaces, beams, post, meter;
  double coldMs = 0.0;
  uint64_t fragments = 0, scattering = 0, refined = 0;
  int beamsInView = 0, shadowSize = 0, lightLayers = 0;
  double beamsPerTile = 0.0;
  std::vector<std::string> warnings;
  std::vector<double> mapsPerFrame;  // with --move: shadow maps drawn and light maps baked
  int mapsPendingMax = 0;
  const FrameState still = frame;
  for (int f = 0; f <= frames; ++f) {
    if (moveDeg > 0.0 && f > 0) frame = turnedBeams(still, static_cast<float>(moveDeg * f));
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = processCpuMs();
    (*renderer)->render(frame);
    // As a PNG is made: metered (auto exposure), then encoded.
    const Metering metered = (*renderer)->meter();
    (void)(*renderer)->readDisplay({.exposureEv = metered.ev});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const PassTimes& t = (*renderer)->lastTimes();
    if (f == 0) {  // shadow maps and light maps are made here, cached after
      coldMs = ms;
      warnings = (*renderer)->warnings();
      for (const std::string& w : warnings) std::fprintf(stderr, "haze bench: warning: %s\n", w.c_str());
      continue;
    }
    total.push_back(ms);
    cpu.push_back(processCpuMs() - cpu0);
    mapsPerFrame.push_back(t.shadowMapsRendered + t.lightMapsBaked);
    mapsPendingMax = std::max(mapsPendingMax, t.mapsPending);
    if (dense) {
      for (int pass = f == 1 ? 0 : 1; pass < 2; ++pass) {  // a cold frame first, as above
        const auto d0 = std::chrono::steady_clock::now();
        const double dcpu0 = processCpuMs();
        dense->render(denseFrame);
        const Metering m = dense->meter();
        (void)dense->readDisplay({.exposureEv = m.ev});
        const double dms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - d0).count();
        if (pass == 0) {
          denseColdMs = dms;
          continue;
        }
        denseTotal.push_back(dms);
        denseCpu.push_back(processCpuMs() - dcpu0);
        denseBeams.push_back(dense->lastTimes().beamsMs);
        denseSurfaces.push_back(dense->lastTimes().surfacesMs);
        denseParticles.push_back(dense->lastTimes().particlesMs);
        denseGenerate.push_back(dense->lastTimes().particlesGenerateMs);
      }
    }
    if (unculled) {
      for (int pass = f == 1 ? 0 : 1; pass < 2; ++pass) {
        const auto u0 = std::chrono::steady_clock::now();
        unculled->render(frame);
        const Metering m = unculled->meter();
        (void)unculled->readDisplay({.exposureEv = m.ev});
        if (pass == 0) continue;
        unculledTotal.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - u0).count());
        unculledSurfaces.push_back(unculled->lastTimes().surfacesMs);
      }
    }
    bodyMeshesDrawn = t.bodyMeshesDrawn;
    shadow.push_back(t.shadowMapsMs);
    surfaces.push_back(t.surfacesMs);
    beams.push_back(t.beamsMs);
    post.push_back(t.postMs);
    meter.push_back(t.meterMs);
    fragments = t.planeFragments;
    scattering = t.scatteringFragments;
    refined = t.refinedPixels;
    beamsInView = t.beamsDrawn;
    beamsPerTile = t.beamsPerTile;
    shadowSize = t.shadowMapSize;
    lightLayers = t.lightMapLayers;
  }
  const RenderSettings rs = (*renderer)->settings();
  nlohmann::ordered_json out;
  out["device"] = (*ctx)->description();
  out["width"] = width;
  out["height"] = height;
  if (!showPath.empty()) out["show"] = showPath;
  out["fixtures"] = fixtures;
  out["beams"] = frame.beams.size();
  out["beams_in_view"] = beamsInView;
  out["quality"] = quality;
  out["planes_per_beam"] = rs.planes;
  out["scatter_divisor"] = rs.scatterDivisor;
  out["min_samples_per_chord"] = rs.minSamplesPerChord;
  out["refine_curvature"] = rs.refineCurvature;
  out["jittered_frames"] = rs.frames;
  out["frames_measured"] = frames;
  out["median_frame_ms"] = median(total);
  out["median_frame_cpu_ms"] = median(cpu);
  out["cold_frame_ms"] = coldMs;
  out["pass_ms"] = {{"shadow_maps", median(shadow)}, {"surfaces", median(surfaces)}, {"planes", median(beams)},
                    {"post", median(post)}, {"meter", median(meter)}};
  out["plane_fragments"] = fragments;
  out["scattering_fragments"] = scattering;
  out["refined_pixels"] = refined;
  out["surface_beams_per_tile"] = beamsPerTile;
  out["shadow_map_size"] = shadowSize;
  out["light_map_layers"] = lightLayers;
  out["peak_memory_mb"] = peakMemoryMb();
  out["warnings"] = warnings;
  out["shadows"] = frame.softShadows ? "soft" : "hard";
  if (moveDeg > 0.0)
    out["move"] = {{"degrees_per_frame", moveDeg},
                   {"map_budget_ms", mapBudgetMs},
                   {"longest_frame_ms", *std::max_element(total.begin(), total.end())},
                   {"median_maps_per_frame", median(mapsPerFrame)},
                   {"most_maps_pending", mapsPendingMax}};
  if (dense && compareShadows) {
    const double soft = median(total), hard = median(denseTotal);
    const double softCpu = median(cpu), hardCpu = median(denseCpu);
    out["shadows_compare"] = {{"median_frame_ms_hard", hard},
                              {"median_frame_cpu_ms_hard", hardCpu},
                              {"pass_ms_hard", {{"surfaces", median(denseSurfaces)}, {"planes", median(denseBeams)}}},
                              {"ratio_frame", hard > 0 ? soft / hard : 0.0},
                              {"ratio_cpu", hardCpu > 0 ? softCpu / hardCpu : 0.0},
                              {"ratio_planes", median(denseBeams) > 0 ? median(beams) / median(denseBeams) : 0.0},
                              {"ratio_surfaces",
                               median(denseSurfaces) > 0 ? median(surfaces) / median(denseSurfaces) : 0.0}};
  } else if (dense && compareBodies) {
    const double with = median(total), without = median(denseTotal);
    out["bodies"] = {{"boxes", frame.bodies.size()},
                     {"meshes", frame.bodyMeshes.size()},
                     {"median_frame_ms_without", without},
                     {"pass_ms_without", {{"surfaces", median(denseSurfaces)}, {"planes", median(denseBeams)}}},
                     // The first frame draws every beam's shadow map, with the bodies that can shadow it.
                     {"cold_frame_ms", coldMs},
                     {"cold_frame_ms_without", denseColdMs},
                     {"meshes_in_view", bodyMeshesDrawn},
                     // Every part drawn whole, no frustum or back-face culling.
                     {"median_frame_ms_unculled", median(unculledTotal)},
                     {"surfaces_ms_unculled", median(unculledSurfaces)},
                     {"share_of_frame_unculled",
                      median(unculledTotal) > 0 ? (median(unculledTotal) - without) / median(unculledTotal) : 0.0},
                     {"ratio_frame", without > 0 ? with / without : 0.0},
                     {"share_of_frame", with > 0 ? (with - without) / with : 0.0}};
  } else if (dense && sun) {
    out["sun"] = {{"median_frame_ms", median(denseTotal)},
                  {"cold_frame_ms", denseColdMs},
                  {"pass_ms", {{"surfaces", median(denseSurfaces)}, {"planes", median(denseBeams)}}},
                  {"ratio_frame", median(total) > 0 ? median(denseTotal) / median(total) : 0.0},
                  {"ratio_surfaces", median(surfaces) > 0 ? median(denseSurfaces) / median(surfaces) : 0.0},
                  {"ratio_planes", median(beams) > 0 ? median(denseBeams) / median(beams) : 0.0}};
  } else if (dense && compareParticles) {
    const PassTimes& pt = dense->lastTimes();
    out["particles"] = {{"density_per_m3", particleDensity},
                        {"drawn", pt.particlesDrawn},
                        {"wanted", pt.particlesWanted},
                        {"limit", denseFrame.particles.limit},
                        {"median_frame_ms_with", median(denseTotal)},
                        {"median_frame_cpu_ms_with", median(denseCpu)},
                        {"pass_ms", median(denseParticles)},
                        {"generate_ms", median(denseGenerate)},
                        {"ratio_frame", median(total) > 0 ? median(denseTotal) / median(total) : 0.0},
                        {"ratio_cpu", median(cpu) > 0 ? median(denseCpu) / median(cpu) : 0.0}};
  } else if (dense) {
    out["density"] = {{"grid", densityCells},
                      {"median_frame_ms", median(denseTotal)},
                      {"median_frame_cpu_ms", median(denseCpu)},
                      {"cold_frame_ms", denseColdMs},
                      {"pass_ms", {{"surfaces", median(denseSurfaces)}, {"planes", median(denseBeams)}}},
                      {"ratio_frame", median(total) > 0 ? median(denseTotal) / median(total) : 0.0},
                      {"ratio_cpu", median(cpu) > 0 ? median(denseCpu) / median(cpu) : 0.0},
                      {"ratio_planes", median(beams) > 0 ? median(denseBeams) / median(beams) : 0.0}};
  }
  if (compare) {
    const ImageRGB gpu = (*renderer)->readRadiance();
    const auto t0 = std::chrono::steady_clock::now();
    const ImageRGB ref = renderReference(venue, frame, width, height);
    const double refMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    out["reference_ms"] = refMs;
    auto c = compareImages(gpu, ref);
    if (!c) return fail("against the reference: " + c.error().str());
    out["mean_relative_error"] = c->meanRelError;
    out["speedup_vs_reference"] = median(total) > 0 ? refMs / median(total) : 0.0;
  }
  if (json) {
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("%d fixtures (%zu beams, %d in view) at %dx%d, %s (%d planes, scatter 1/%d, %d samples per chord): "
                "%.1f ms per frame (median of %d; cold %.1f ms)\n", fixtures, frame.beams.size(), beamsInView, width,
                height, quality.c_str(), rs.planes, rs.scatterDivisor, rs.minSamplesPerChord, median(total), frames,
                coldMs);
    std::printf("  shadow maps %.1f  surfaces %.1f  planes %.1f  post %.1f  meter %.1f ms; %llu plane fragments (%llu "
                "scattering); %.0f ms CPU per frame\n", median(shadow), median(surfaces), median(beams),
                median(post), median(meter), static_cast<unsigned long long>(fragments),
                static_cast<unsigned long long>(scattering), median(cpu));
    if (rs.scatterDivisor > 1 && rs.refineCurvature > 0.0f)
      std::printf("  %llu pixels (%.1f %%) refined at full resolution (curvature above %.2f)\n",
                  static_cast<unsigned long long>(refined), 100.0 * static_cast<double>(refined) / (width * height),
                  rs.refineCurvature);
    std::printf("  shadow maps %d px, %d light maps, %.1f beams per lit surface tile; peak memory %.0f MB\n", shadowSize,
                lightLayers, beamsPerTile, peakMemoryMb());
    if (moveDeg > 0.0)
      std::printf("  moving %.2f degrees a frame, map budget %.1f ms (0: none): longest frame %.1f ms, %.0f maps a frame "
                  "(median), at most %d beams on old maps\n", moveDeg, mapBudgetMs,
                  out["move"]["longest_frame_ms"].get<double>(), median(mapsPerFrame), mapsPendingMax);
    if (dense && compareShadows)
      std::printf("  hard shadows: %.1f ms per frame (soft %.2fx), %.0f ms CPU (%.2fx), planes %.1f ms (%.2fx), "
                  "surfaces %.1f ms (%.2fx)\n", median(denseTotal), out["shadows_compare"]["ratio_frame"].get<double>(),
                  median(denseCpu), out["shadows_compare"]["ratio_cpu"].get<double>(), median(denseBeams),
                  out["shadows_compare"]["ratio_planes"].get<double>(), median(denseSurfaces),
                  out["shadows_compare"]["ratio_surfaces"].get<double>());
    else if (dense && compareBodies)
      std::printf("  bodies (%zu boxes, %zu meshes): %.1f ms per frame without them (with them %.2fx, %.1f %% of the "
                  "frame, %d meshes in view); surfaces %.1f ms without; drawn whole (no culling) %.1f ms, %.1f %% of "
                  "the frame, surfaces %.1f ms; cold frame %.1f ms, %.1f without\n",
                  frame.bodies.size(), frame.bodyMeshes.size(), median(denseTotal),
                  out["bodies"]["ratio_frame"].get<double>(), 100 * out["bodies"]["share_of_frame"].get<double>(),
                  bodyMeshesDrawn, median(denseSurfaces), median(unculledTotal),
                  100 * out["bodies"]["share_of_frame_unculled"].get<double>(), median(unculledSurfaces), coldMs,
                  denseColdMs);
    else if (dense && sun)
      std::printf("  with a sun: %.1f ms per frame (%.2fx), surfaces %.1f ms (%.2fx), planes and sun march %.1f ms "
                  "(%.2fx); cold %.1f ms\n", median(denseTotal), out["sun"]["ratio_frame"].get<double>(),
                  median(denseSurfaces), out["sun"]["ratio_surfaces"].get<double>(), median(denseBeams),
                  out["sun"]["ratio_planes"].get<double>(), denseColdMs);
    else if (dense && compareParticles)
      std::printf("  with particles (%.0f per m^3): %zu drawn of %zu wanted (limit %zu), %.1f ms per frame (%.2fx), %.0f ms "
                  "CPU (%.2fx); particle pass %.1f ms, finding them %.1f ms (CPU)\n", particleDensity,
                  dense->lastTimes().particlesDrawn, dense->lastTimes().particlesWanted, denseFrame.particles.limit,
                  median(denseTotal), out["particles"]["ratio_frame"].get<double>(), median(denseCpu),
                  out["particles"]["ratio_cpu"].get<double>(), median(denseParticles), median(denseGenerate));
    else if (dense)
      std::printf("  through a %d^3 density field with a hazer: %.1f ms per frame (%.2fx), %.0f ms CPU (%.2fx), planes "
                  "%.1f ms (%.2fx), surfaces %.1f ms; cold %.1f ms\n", densityCells, median(denseTotal),
                  out["density"]["ratio_frame"].get<double>(), median(denseCpu), out["density"]["ratio_cpu"].get<double>(),
                  median(denseBeams), out["density"]["ratio_planes"].get<double>(), median(denseSurfaces), denseColdMs);
    if (compare)
      std::printf("  reference %.0f ms, mean relative error %.4f, %.0fx faster\n", out["reference_ms"].get<double>(),
                  out["mean_relative_error"].get<double>(), out["speedup_vs_reference"].get<double>());
  }
  return 0;
}

}  // namespace haze
