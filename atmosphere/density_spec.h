// What a show says about the density of its haze (docs/shows.md, "Density"): a base density,
// a ground-fog layer, boxes of their own density and hazers, moved by a room air flow. Plain
// data: the show model holds it, atmosphere/density_sim.h turns it into a field.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

namespace haze {

struct FogLayerSpec {
  float density = 0.0f;   // D added at and below heightM
  float heightM = 0.5f;   // the layer's top, metres above y = 0
  float falloffM = 0.3f;  // above the top the fog's density falls as exp(-(y - heightM) / falloffM)
  bool operator==(const FogLayerSpec&) const = default;
};

struct DensityBoxSpec {
  glm::vec3 minM{0.0f}, maxM{0.0f};
  float density = 1.0f;   // D inside the box, in place of base and fog
  bool operator==(const DensityBoxSpec&) const = default;
};

struct HazerSpec {
  glm::vec3 positionM{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // where the nozzle and its fan blow (normalised on use)
  float output = 1.0f;    // m^3 per second of haze at D = 1
  float spreadDeg = 30.0f;  // the fan's full cone angle
  float speedMps = 2.0f;  // the fan's air speed at the nozzle
  bool operator==(const HazerSpec&) const = default;
};

// The grid's limits: more cells than this is refused (docs/shows.md), at most this per side.
inline constexpr int kMaxDensityCellsPerSide = 256;
inline constexpr long long kMaxDensityCells = 128LL * 128 * 128 * 4;  // 8 M cells, ~100 MB while simulating

struct DensitySpec {
  float base = 1.0f;
  std::optional<FogLayerSpec> fog;
  std::vector<DensityBoxSpec> boxes;
  std::vector<HazerSpec> hazers;
  glm::vec3 airFlowMps{0.0f};  // the room's air, uniform
  float mixingM2ps = 0.05f;    // turbulent diffusion of the haze [m^2/s]
  float dissipationPerS = 0.0f;  // the hazers' haze decays as exp(-dissipation t)
  int grid[3] = {64, 64, 64};  // cells along x, y, z
  // The grid's box; none: the venue's bounds.
  std::optional<glm::vec3> boundsMinM, boundsMaxM;
  // The field at playback time t is the simulation after warmup + t seconds of the hazers
  // running (still: warmup seconds, whatever t).
  double warmupS = 60.0;
  bool still = false;
  bool operator==(const DensitySpec& o) const {
    return base == o.base && fog == o.fog && boxes == o.boxes && hazers == o.hazers && airFlowMps == o.airFlowMps &&
           mixingM2ps == o.mixingM2ps && dissipationPerS == o.dissipationPerS && grid[0] == o.grid[0] &&
           grid[1] == o.grid[1] && grid[2] == o.grid[2] && boundsMinM == o.boundsMinM && boundsMaxM == o.boundsMaxM &&
           warmupS == o.warmupS && still == o.still;
  }
};

}  // namespace haze
