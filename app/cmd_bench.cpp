// haze bench [--fixtures N | --show SHOW [--cue N] [--camera NAME]] [--width W --height H] [--quality Q]
//            [--frames K] [--move DEG [--map-budget MS]] [--compare-reference] --json
//            [--planes N] [--scatter-divisor D] [--min-samples M] (override the preset's values)
// Renders the bench scene (app/bench_scene.*) or a show's cue headless and reports the median
// time per frame and per pass, with shadow and light maps cached after the first (cold) frame,
// as while a designer looks at a cue; the cold frame is reported apart. A comparison (a density
// field, the bodies, hard shadows, a sun, particles) renders a variant of the frame on a second
// renderer, alternating frame by frame with the base so that both see the same load, and gives
// the ratios: each is one row of kComparisons, run by the same loop.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "app/bench_scene.h"
#include "app/bench_show.h"
#include "app/bench_study.h"
#include "app/command_line.h"
#include "app/commands.h"
#include "app/render_session.h"
#include "atmosphere/density_sim.h"
#include "renderer/context.h"
#include "renderer/reference/reference.h"
#include "renderer/renderer.h"
#include "shows/scene/image_compare.h"
#include "shows/scene/physics.h"

namespace haze {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kBenchUsage =
    "usage: haze bench [--fixtures N | --show SHOW [--cue N] [--camera NAME] [--cells auto|separate|merged]]\n"
    "                  [--width W --height H] [--quality Q] [--frames K] [--planes N] [--scatter-divisor D]\n"
    "                  [--min-samples M] [--refine C] [--density N] [--no-bodies | --compare-bodies] [--sun]\n"
    "                  [--shadows soft|hard|compare] [--compare-particles [--particle-density N]]\n"
    "                  [--move DEG [--map-budget MS]] [--compare-reference] [--json]\n"
    "       haze bench --study [--width W --height H]\n"
    "Times the synthetic stage (N fixtures, 16 by default; the stage grows with N) or a show's cue (the\n"
    "first unless --cue, from the show's first camera unless --camera) per frame and per pass;\n"
    "--cells as haze render (docs/cells.md; auto by default);\n"
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

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

struct BenchOptions {
  int fixtures = -1, width = 1280, height = 720, frames = 5;
  std::string quality = "default", showPath, cue, camera, cells = "auto", shadows;
  bool json = false, compareReference = false, study = false, noBodies = false, compareBodies = false, sun = false,
       compareParticles = false;
  double particleDensity = ParticleSettings{}.densityPerM3;
  int planes = 0, divisor = 0, minSamples = -1;  // 0 / -1: the preset's
  double refine = -1.0;                            // -1: the preset's
  int densityCells = 0;
  double moveDeg = 0.0, mapBudgetMs = 0.0;
};

// The command line that fills `o` (it keeps references to o's fields).
CommandLine benchCommandLine(BenchOptions& o) {
  CommandLine cli("haze bench", kBenchUsage);
  cli.integer("--fixtures", o.fixtures, 0, 4096, "0..4096")
      .text("--show", o.showPath, "a show file")
      .text("--cue", o.cue, "a cue number")
      .text("--camera", o.camera, "a camera name")
      .integer("--width", o.width, 1, 16384, "1..16384")
      .integer("--height", o.height, 1, 16384, "1..16384")
      .integer("--frames", o.frames, 1, 1000, "1..1000")
      .choice("--quality", o.quality, {"draft", "default", "high", "reference"})
      .flag("--json", o.json)
      .flag("--compare-reference", o.compareReference)
      .flag("--no-bodies", o.noBodies)
      .flag("--compare-bodies", o.compareBodies)
      .flag("--sun", o.sun)
      .flag("--compare-particles", o.compareParticles)
      .number("--particle-density", o.particleDensity, 0.0, kMaxParticleDensityPerM3, "particles per m^3, 0..5000")
      .flag("--study", o.study)
      .integer("--planes", o.planes, 1, 4096, "1..4096")
      .integer("--scatter-divisor", o.divisor, 1, 8, "1..8")
      .integer("--min-samples", o.minSamples, 0, 256, "0..256")
      .number("--refine", o.refine, 0.0, 2.0, "0..2 (0 = no refinement)")
      .integer("--density", o.densityCells, 2, kMaxDensityCellsPerSide, "2..256 cells per side")
      .choice("--cells", o.cells, cellBeamsNames())
      .choice("--shadows", o.shadows, {"soft", "hard", "compare"})
      .number("--move", o.moveDeg, 0.0, 90.0, "0..90 degrees per frame")
      .number("--map-budget", o.mapBudgetMs, 0.0, 1e6, "milliseconds, 0 = unlimited");
  return cli;
}

// The options that exclude each other, as one line; none when the combination is good.
std::optional<std::string> conflict(const BenchOptions& o) {
  const bool compareShadows = o.shadows == "compare", density = o.densityCells > 0;
  if (!o.showPath.empty() && o.fixtures >= 0) return "--fixtures and --show exclude each other";
  if (o.showPath.empty() && (!o.cue.empty() || !o.camera.empty())) return "--cue and --camera need --show";
  if (o.showPath.empty() && o.cells != "auto") return "--cells needs --show";
  if (o.noBodies && o.compareBodies) return "--no-bodies and --compare-bodies exclude each other";
  if (o.compareBodies && density) return "--compare-bodies and --density exclude each other";
  if (compareShadows && (o.compareBodies || density || o.sun || o.compareParticles))
    return "--shadows compare excludes --compare-bodies, --density, --sun and --compare-particles";
  if (o.sun && (o.compareBodies || density || o.compareParticles))
    return "--sun excludes --density, --compare-bodies and --compare-particles";
  if (o.compareParticles && (o.compareBodies || density))
    return "--compare-particles excludes --compare-bodies and --density";
  if (o.mapBudgetMs > 0.0 && o.moveDeg <= 0.0) return "--map-budget needs --move";
  if (o.moveDeg > 0.0 && (o.compareBodies || density || o.sun || o.compareParticles || compareShadows))
    return "--move excludes --density, --compare-bodies, --sun, --compare-particles and --shadows compare";
  return std::nullopt;
}

RenderSettings benchSettings(const BenchOptions& o, Quality quality) {
  RenderSettings settings = renderSettingsFor(quality, o.width, o.height);
  settings.timePasses = true;
  if (o.planes > 0) settings.planes = o.planes;
  if (o.divisor > 0) settings.scatterDivisor = o.divisor;
  if (o.minSamples >= 0) settings.minSamplesPerChord = o.minSamples;
  if (o.refine >= 0.0) settings.refineCurvature = static_cast<float>(o.refine);
  settings.mapWorkBudgetMs = o.mapBudgetMs;
  return settings;
}

// One renderer's frames: each rendered, metered and read back as a PNG is made. The cold frame
// (its shadow and light maps made) is kept apart; the maps are cached for the others.
struct Samples {
  std::vector<double> total, cpu, shadow, surfaces, beams, post, meter, particles, generate, maps;
  double coldMs = 0.0;
  int mapsPendingMax = 0;
  PassTimes last;

  void render(Renderer& r, const FrameState& frame, bool cold) {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = processCpuMs();
    r.render(frame);
    const Metering metered = r.meter();
    (void)r.readDisplay({.exposureEv = metered.ev});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    last = r.lastTimes();
    if (cold) {
      coldMs = ms;
      return;
    }
    total.push_back(ms);
    cpu.push_back(processCpuMs() - cpu0);
    using Sample = std::pair<std::vector<double>*, double>;
    for (auto [list, value] : std::initializer_list<Sample>{
             {&shadow, last.shadowMapsMs}, {&surfaces, last.surfacesMs}, {&beams, last.beamsMs}, {&post, last.postMs},
             {&meter, last.meterMs}, {&particles, last.particlesMs}, {&generate, last.particlesGenerateMs}})
      list->push_back(value);
    maps.push_back(last.shadowMapsRendered + last.lightMapsBaked);
    mapsPendingMax = std::max(mapsPendingMax, last.mapsPending);
  }
  double median(const std::vector<double> Samples::*list) const { return medianOf(this->*list); }
};

// A variant of the frame on a renderer of its own (and, for the bodies, a third: every mesh
// drawn whole), alternated with the base.
struct Comparison {
  FrameState frame;
  std::unique_ptr<Renderer> renderer, unculled;
  Samples samples, unculledSamples;
};

struct BenchRun {
  const BenchOptions& o;
  const FrameState& frame;  // the base frame
  const Samples& base;
  const Comparison& c;
};

// The comparison modes: when one is asked for, how its frame (and the base's) differ, its JSON
// object and its line of text. Each mode is one row; the loop that renders them is one.
struct ComparisonMode {
  const char* key;
  std::function<bool(const BenchOptions&)> asked;
  std::function<void(const BenchOptions&, const Venue&, FrameState& base, FrameState& variant)> vary;
  std::function<Json(const BenchRun&)> json;
  std::function<std::string(const BenchRun&, const Json&)> text;
};

std::string format(const char* fmt, auto... values) {
  char line[1024];
  std::snprintf(line, sizeof line, fmt, values...);
  return line;
}

Json passesOf(const Samples& s) {
  return {{"surfaces", s.median(&Samples::surfaces)}, {"planes", s.median(&Samples::beams)}};
}

using S = Samples;
const std::vector<ComparisonMode> kComparisons{
      {"density", [](const BenchOptions& o) { return o.densityCells > 0; },
       [](const BenchOptions& o, const Venue& venue, FrameState&, FrameState& variant) {
         DensitySpec spec = benchDensity(o.densityCells);
         DensitySim sim(spec, densityGrid(spec, venue.boundsMin, venue.boundsMax));
         variant.medium.density = std::make_shared<DensityField>(sim.fieldAt(spec.warmupS));
       },
       [](const BenchRun& r) {
         const S &b = r.base, &v = r.c.samples;
         return Json{{"grid", r.o.densityCells},
                     {"median_frame_ms", v.median(&S::total)},
                     {"median_frame_cpu_ms", v.median(&S::cpu)},
                     {"cold_frame_ms", v.coldMs},
                     {"pass_ms", passesOf(v)},
                     {"ratio_frame", ratio(v.median(&S::total), b.median(&S::total))},
                     {"ratio_cpu", ratio(v.median(&S::cpu), b.median(&S::cpu))},
                     {"ratio_planes", ratio(v.median(&S::beams), b.median(&S::beams))}};
       },
       [](const BenchRun& r, const Json& j) {
         const S& v = r.c.samples;
         return format("  through a %d^3 density field with a hazer: %.1f ms per frame (%.2fx), %.0f ms CPU (%.2fx), "
                       "planes %.1f ms (%.2fx), surfaces %.1f ms; cold %.1f ms\n",
                       r.o.densityCells, v.median(&S::total), j["ratio_frame"].get<double>(), v.median(&S::cpu),
                       j["ratio_cpu"].get<double>(), v.median(&S::beams), j["ratio_planes"].get<double>(),
                       v.median(&S::surfaces), v.coldMs);
       }},
      // Without the bodies: what they cost; with every mesh drawn whole (RenderSettings::cullBodies
      // off, the third renderer): what the culling saves.
      {"bodies", [](const BenchOptions& o) { return o.compareBodies; },
       [](const BenchOptions&, const Venue&, FrameState&, FrameState& variant) {
         variant.bodies.clear();
         variant.bodyMeshes.clear();
       },
       [](const BenchRun& r) {
         const S &b = r.base, &v = r.c.samples, &u = r.c.unculledSamples;
         const double with = b.median(&S::total), without = v.median(&S::total), whole = u.median(&S::total);
         return Json{{"boxes", r.frame.bodies.size()},
                     {"meshes", r.frame.bodyMeshes.size()},
                     {"median_frame_ms_without", without},
                     {"pass_ms_without", passesOf(v)},
                     // The first frame draws every beam's shadow map, with the bodies that can shadow it.
                     {"cold_frame_ms", b.coldMs},
                     {"cold_frame_ms_without", v.coldMs},
                     {"meshes_in_view", b.last.bodyMeshesDrawn},
                     {"median_frame_ms_unculled", whole},
                     {"surfaces_ms_unculled", u.median(&S::surfaces)},
                     {"share_of_frame_unculled", ratio(whole - without, whole)},
                     {"ratio_frame", ratio(with, without)},
                     {"share_of_frame", ratio(with - without, with)}};
       },
       [](const BenchRun& r, const Json& j) {
         const S &b = r.base, &v = r.c.samples, &u = r.c.unculledSamples;
         return format("  bodies (%zu boxes, %zu meshes): %.1f ms per frame without them (with them %.2fx, %.1f %% of "
                       "the frame, %d meshes in view); surfaces %.1f ms without; drawn whole (no culling) %.1f ms, "
                       "%.1f %% of the frame, surfaces %.1f ms; cold frame %.1f ms, %.1f without\n",
                       r.frame.bodies.size(), r.frame.bodyMeshes.size(), v.median(&S::total),
                       j["ratio_frame"].get<double>(), 100 * j["share_of_frame"].get<double>(),
                       b.last.bodyMeshesDrawn, v.median(&S::surfaces), u.median(&S::total),
                       100 * j["share_of_frame_unculled"].get<double>(), u.median(&S::surfaces), b.coldMs, v.coldMs);
       }},
      {"shadows_compare", [](const BenchOptions& o) { return o.shadows == "compare"; },
       [](const BenchOptions&, const Venue&, FrameState&, FrameState& variant) { variant.softShadows = false; },
       [](const BenchRun& r) {
         const S &soft = r.base, &hard = r.c.samples;
         return Json{{"median_frame_ms_hard", hard.median(&S::total)},
                     {"median_frame_cpu_ms_hard", hard.median(&S::cpu)},
                     {"pass_ms_hard", passesOf(hard)},
                     {"ratio_frame", ratio(soft.median(&S::total), hard.median(&S::total))},
                     {"ratio_cpu", ratio(soft.median(&S::cpu), hard.median(&S::cpu))},
                     {"ratio_planes", ratio(soft.median(&S::beams), hard.median(&S::beams))},
                     {"ratio_surfaces", ratio(soft.median(&S::surfaces), hard.median(&S::surfaces))}};
       },
       [](const BenchRun& r, const Json& j) {
         const S& hard = r.c.samples;
         return format("  hard shadows: %.1f ms per frame (soft %.2fx), %.0f ms CPU (%.2fx), planes %.1f ms (%.2fx), "
                       "surfaces %.1f ms (%.2fx)\n",
                       hard.median(&S::total), j["ratio_frame"].get<double>(), hard.median(&S::cpu),
                       j["ratio_cpu"].get<double>(), hard.median(&S::beams), j["ratio_planes"].get<double>(),
                       hard.median(&S::surfaces), j["ratio_surfaces"].get<double>());
       }},
      // The base frame then has no sun at all (a show's own is left out).
      {"sun", [](const BenchOptions& o) { return o.sun; },
       [](const BenchOptions&, const Venue&, FrameState& base, FrameState& variant) {
         base.sun = SunState{};
         variant.sun = SunState{.on = true, .direction = sunDirection(250.0f, 35.0f), .illuminance = glm::vec3(50000.0f)};
       },
       [](const BenchRun& r) {
         const S &b = r.base, &v = r.c.samples;
         return Json{{"median_frame_ms", v.median(&S::total)},
                     {"cold_frame_ms", v.coldMs},
                     {"pass_ms", passesOf(v)},
                     {"ratio_frame", ratio(v.median(&S::total), b.median(&S::total))},
                     {"ratio_surfaces", ratio(v.median(&S::surfaces), b.median(&S::surfaces))},
                     {"ratio_planes", ratio(v.median(&S::beams), b.median(&S::beams))}};
       },
       [](const BenchRun& r, const Json& j) {
         const S& v = r.c.samples;
         return format("  with a sun: %.1f ms per frame (%.2fx), surfaces %.1f ms (%.2fx), planes and sun march %.1f "
                       "ms (%.2fx); cold %.1f ms\n",
                       v.median(&S::total), j["ratio_frame"].get<double>(), v.median(&S::surfaces),
                       j["ratio_surfaces"].get<double>(), v.median(&S::beams), j["ratio_planes"].get<double>(),
                       v.coldMs);
       }},
      {"particles", [](const BenchOptions& o) { return o.compareParticles; },
       [](const BenchOptions& o, const Venue&, FrameState&, FrameState& variant) {
         variant.particles.settings.enabled = true;
         variant.particles.settings.densityPerM3 = static_cast<float>(o.particleDensity);
       },
       [](const BenchRun& r) {
         const S &b = r.base, &v = r.c.samples;
         return Json{{"density_per_m3", r.o.particleDensity},
                     {"drawn", v.last.particlesDrawn},
                     {"wanted", v.last.particlesWanted},
                     {"limit", r.c.frame.particles.limit},
                     {"median_frame_ms_with", v.median(&S::total)},
                     {"median_frame_cpu_ms_with", v.median(&S::cpu)},
                     {"pass_ms", v.median(&S::particles)},
                     {"generate_ms", v.median(&S::generate)},
                     {"ratio_frame", ratio(v.median(&S::total), b.median(&S::total))},
                     {"ratio_cpu", ratio(v.median(&S::cpu), b.median(&S::cpu))}};
       },
       [](const BenchRun& r, const Json& j) {
         const S& v = r.c.samples;
         return format("  with particles (%.0f per m^3): %zu drawn of %zu wanted (limit %zu), %.1f ms per frame "
                       "(%.2fx), %.0f ms CPU (%.2fx); particle pass %.1f ms, finding them %.1f ms (CPU)\n",
                       r.o.particleDensity, v.last.particlesDrawn, v.last.particlesWanted, r.c.frame.particles.limit,
                       v.median(&S::total), j["ratio_frame"].get<double>(), v.median(&S::cpu),
                       j["ratio_cpu"].get<double>(), v.median(&S::particles), v.median(&S::generate));
       }},
};

// The base frame K + 1 times (the first cold), turned by --move each frame; a comparison's
// frames alternate with it, its own cold frame just before its first measured one. Returns the
// warnings of the cold frame (printed once).
std::vector<std::string> runFrames(const BenchOptions& o, Renderer& renderer, const FrameState& still,
                                   FrameState& frame, Samples& base, Comparison* c) {
  std::vector<std::string> warnings;
  for (int f = 0; f <= o.frames; ++f) {
    if (o.moveDeg > 0.0 && f > 0) frame = turnedBeams(still, static_cast<float>(o.moveDeg * f));
    base.render(renderer, frame, f == 0);
    if (f == 0) {
      warnings = renderer.warnings();
      for (const std::string& w : warnings) std::fprintf(stderr, "haze bench: warning: %s\n", w.c_str());
      continue;
    }
    if (!c) continue;
    for (int pass = f == 1 ? 0 : 1; pass < 2; ++pass) {
      c->samples.render(*c->renderer, c->frame, pass == 0);
      if (c->unculled) c->unculledSamples.render(*c->unculled, frame, pass == 0);
    }
  }
  return warnings;
}

Json baseJson(const BenchOptions& o, const std::string& device, const RenderSettings& rs, const FrameState& frame,
              const Samples& b, const std::vector<std::string>& warnings) {
  const PassTimes& t = b.last;
  Json out;
  out["device"] = device;
  out["width"] = o.width;
  out["height"] = o.height;
  if (!o.showPath.empty()) out["show"] = o.showPath;
  out["fixtures"] = o.fixtures;
  out["beams"] = frame.beams.size();
  out["beams_in_view"] = t.beamsDrawn;
  out["quality"] = o.quality;
  out["planes_per_beam"] = rs.planes;
  out["scatter_divisor"] = rs.scatterDivisor;
  out["min_samples_per_chord"] = rs.minSamplesPerChord;
  out["refine_curvature"] = rs.refineCurvature;
  out["jittered_frames"] = rs.frames;
  out["frames_measured"] = o.frames;
  out["median_frame_ms"] = b.median(&Samples::total);
  out["median_frame_cpu_ms"] = b.median(&Samples::cpu);
  out["cold_frame_ms"] = b.coldMs;
  out["pass_ms"] = {{"shadow_maps", b.median(&Samples::shadow)}, {"surfaces", b.median(&Samples::surfaces)},
                    {"planes", b.median(&Samples::beams)}, {"post", b.median(&Samples::post)},
                    {"meter", b.median(&Samples::meter)}};
  out["plane_fragments"] = t.planeFragments;
  out["scattering_fragments"] = t.scatteringFragments;
  out["refined_pixels"] = t.refinedPixels;
  out["surface_beams_per_tile"] = t.beamsPerTile;
  out["shadow_map_size"] = t.shadowMapSize;
  out["light_map_layers"] = t.lightMapLayers;
  out["peak_memory_mb"] = peakMemoryMb();
  out["warnings"] = warnings;
  out["shadows"] = frame.softShadows ? "soft" : "hard";
  if (o.moveDeg > 0.0)
    out["move"] = {{"degrees_per_frame", o.moveDeg},
                   {"map_budget_ms", o.mapBudgetMs},
                   {"longest_frame_ms", *std::max_element(b.total.begin(), b.total.end())},
                   {"median_maps_per_frame", b.median(&Samples::maps)},
                   {"most_maps_pending", b.mapsPendingMax}};
  return out;
}

void printText(const BenchOptions& o, const RenderSettings& rs, const FrameState& frame, const Samples& b,
               const Json& out) {
  const PassTimes& t = b.last;
  std::printf("%d fixtures (%zu beams, %d in view) at %dx%d, %s (%d planes, scatter 1/%d, %d samples per chord): "
              "%.1f ms per frame (median of %d; cold %.1f ms)\n", o.fixtures, frame.beams.size(), t.beamsDrawn,
              o.width, o.height, o.quality.c_str(), rs.planes, rs.scatterDivisor, rs.minSamplesPerChord,
              b.median(&Samples::total), o.frames, b.coldMs);
  std::printf("  shadow maps %.1f  surfaces %.1f  planes %.1f  post %.1f  meter %.1f ms; %llu plane fragments (%llu "
              "scattering); %.0f ms CPU per frame\n", b.median(&Samples::shadow), b.median(&Samples::surfaces),
              b.median(&Samples::beams), b.median(&Samples::post), b.median(&Samples::meter),
              static_cast<unsigned long long>(t.planeFragments), static_cast<unsigned long long>(t.scatteringFragments),
              b.median(&Samples::cpu));
  if (rs.scatterDivisor > 1 && rs.refineCurvature > 0.0f)
    std::printf("  %llu pixels (%.1f %%) refined at full resolution (curvature above %.2f)\n",
                static_cast<unsigned long long>(t.refinedPixels),
                100.0 * static_cast<double>(t.refinedPixels) / (o.width * o.height), rs.refineCurvature);
  std::printf("  shadow maps %d px, %d light maps, %.1f beams per lit surface tile; peak memory %.0f MB\n",
              t.shadowMapSize, t.lightMapLayers, t.beamsPerTile, peakMemoryMb());
  if (o.moveDeg > 0.0)
    std::printf("  moving %.2f degrees a frame, map budget %.1f ms (0: none): longest frame %.1f ms, %.0f maps a frame "
                "(median), at most %d beams on old maps\n", o.moveDeg, o.mapBudgetMs,
                out["move"]["longest_frame_ms"].get<double>(), b.median(&Samples::maps), b.mapsPendingMax);
}

// --compare-reference: the CPU reference of the last frame, its time and the error against it.
Status compareWithReference(const Venue& venue, const FrameState& frame, const BenchOptions& o, const Renderer& r,
                            const Samples& b, Json& out) {
  const ImageRGB gpu = r.readRadiance();
  const auto t0 = std::chrono::steady_clock::now();
  const ImageRGB ref = renderReference(venue, frame, o.width, o.height);
  const double refMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  auto c = compareImages(gpu, ref);
  if (!c) return Error{"", "", "against the reference: " + c.error().str()};
  out["reference_ms"] = refMs;
  out["mean_relative_error"] = c->meanRelError;
  out["speedup_vs_reference"] = ratio(refMs, b.median(&Samples::total));
  return Ok{};
}

// The bench scene of --fixtures N, or the show's cue (the show checked as `haze validate` checks
// it: its problems are printed and the command exits kExitBadInput).
std::optional<int> loadFrame(const CommandLine& cli, BenchOptions& o, Venue& venue, FrameState& frame) {
  if (o.showPath.empty()) {
    o.fixtures = o.fixtures < 0 ? 16 : o.fixtures;
    venue = benchVenue(o.fixtures);
    frame = benchFrame(o.fixtures);
    frame.softShadows = true;  // as a show has them unless it asks for hard ones
  } else {
    auto checked = cli.readShow(o.showPath);
    if (!checked) return kExitBadInput;
    if (Status s = loadBenchShow(checked->show, checked->profiles, o.cue, o.camera, cellBeamsNamed(o.cells), venue, frame,
                                 o.fixtures);
        !s)
      return cli.fail(s.error().str());
  }
  if (!o.shadows.empty()) frame.softShadows = o.shadows != "hard";  // compare: soft, against a hard variant
  if (o.noBodies) {  // the fixtures' housings left out, as haze render --no-bodies does
    frame.bodies.clear();
    frame.bodyMeshes.clear();
  }
  return std::nullopt;
}

// The comparison asked for, if any: its frame varied from the base, on renderers of its own.
Result<std::optional<Comparison>> makeComparison(const BenchOptions& o, const Venue& venue,
                                                 const RenderSettings& settings, FrameState& frame,
                                                 const ComparisonMode*& mode) {
  mode = nullptr;
  for (const ComparisonMode& m : kComparisons)
    if (m.asked(o)) mode = &m;
  if (!mode) return std::optional<Comparison>{};
  Comparison c;
  c.frame = frame;
  mode->vary(o, venue, frame, c.frame);
  auto r = Renderer::create(venue, settings);
  if (!r) return r.error();
  c.renderer = std::move(*r);
  if (o.compareBodies) {
    RenderSettings whole = settings;
    whole.cullBodies = false;
    auto u = Renderer::create(venue, whole);
    if (!u) return u.error();
    c.unculled = std::move(*u);
  }
  return std::optional<Comparison>{std::move(c)};
}

}  // namespace

int runBench(const Args& args) {
  BenchOptions o;
  const CommandLine cli = benchCommandLine(o);
  if (auto done = cli.parse(args)) return *done;
  auto q = parseQuality(o.quality);
  if (!q) return fail(q.error().str());
  if (*q == Quality::Reference)
    return cli.usage("--quality reference is the CPU integrator: time it against a GPU preset with --compare-reference");
  if (auto why = conflict(o)) return cli.usage(*why);
  auto ctx = createHeadlessContext();
  if (!ctx) return fail(ctx.error().str());
  if (o.study) return runStudy(o.width, o.height);
  Venue venue;
  FrameState frame;
  if (auto failed = loadFrame(cli, o, venue, frame)) return *failed;
  const RenderSettings settings = benchSettings(o, *q);
  auto renderer = Renderer::create(venue, settings);
  if (!renderer) return fail(renderer.error().str());
  const ComparisonMode* mode = nullptr;
  auto comparison = makeComparison(o, venue, settings, frame, mode);
  if (!comparison) return fail(comparison.error().str());

  Samples base;
  const FrameState still = frame;
  const std::vector<std::string> warnings =
      runFrames(o, **renderer, still, frame, base, *comparison ? &**comparison : nullptr);
  const RenderSettings rs = (*renderer)->settings();
  Json out = baseJson(o, (*ctx)->description(), rs, frame, base, warnings);
  std::string comparisonText;
  if (mode) {
    const BenchRun run{o, frame, base, **comparison};
    out[mode->key] = mode->json(run);
    comparisonText = mode->text(run, out[mode->key]);
  }
  if (o.compareReference)
    if (Status s = compareWithReference(venue, frame, o, **renderer, base, out); !s) return fail(s.error().message);
  if (o.json) {
    std::printf("%s\n", out.dump(2).c_str());
    return 0;
  }
  printText(o, rs, frame, base, out);
  std::fputs(comparisonText.c_str(), stdout);
  if (o.compareReference)
    std::printf("  reference %.0f ms, mean relative error %.4f, %.0fx faster\n", out["reference_ms"].get<double>(),
                out["mean_relative_error"].get<double>(), out["speedup_vs_reference"].get<double>());
  return 0;
}

}  // namespace haze
