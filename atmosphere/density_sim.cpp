// The hazers' haze c(x, t) obeys dc/dt + div(u c) = div(K grad c) + sources - dissipation c on
// the grid, with closed walls (no flux through the grid's faces). Finite volumes: donor-cell
// (upwind) advection and central diffusion as fluxes through the faces between cells, so what
// leaves one cell enters its neighbour and the total changes only by the sources and the
// dissipation (a unit test checks 1 %). The step keeps every cell's outflow below its content
// (no negative haze): dt <= 0.9 / (sum |u| / h + 2 K sum 1 / h^2).
#include "atmosphere/density_sim.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace haze {
namespace {

constexpr double kMaxStepS = 0.5;
constexpr float kPiF = 3.14159265358979f;

// The air a hazer's fan blows at x: along its direction, inside a cone of the fan's spread,
// slowing as the jet widens (speed * r0 / width, a round jet's centreline falls as 1 / s).
glm::vec3 fanVelocity(const HazerSpec& h, const glm::vec3& dir, float r0, const glm::vec3& x) {
  const glm::vec3 r = x - h.positionM;
  const float s = glm::dot(r, dir);
  if (!(s > 0.0f)) return glm::vec3(0.0f);
  const float perp = glm::length(r - s * dir);
  const float halfRad = std::clamp(h.spreadDeg, 1.0f, 160.0f) * 0.5f * kPiF / 180.0f;
  const float width = r0 + s * std::tan(halfRad);
  const float q = perp / width;
  return dir * (h.speedMps * (r0 / width) * std::exp(-q * q));
}

}  // namespace

DensityGrid densityGrid(const DensitySpec& spec, const glm::vec3& venueMinM, const glm::vec3& venueMaxM) {
  DensityGrid g;
  for (int k = 0; k < 3; ++k) g.n[k] = spec.grid[k];
  g.minM = spec.boundsMinM.value_or(venueMinM);
  g.maxM = spec.boundsMaxM.value_or(venueMaxM);
  for (int k = 0; k < 3; ++k) {  // an empty or flat venue still gets a box of some height
    if (!(g.maxM[k] - g.minM[k] >= 0.1f)) {
      const float mid = 0.5f * (g.minM[k] + g.maxM[k]);
      g.minM[k] = mid - 0.05f;
      g.maxM[k] = mid + 0.05f;
    }
  }
  return g;
}

long long densitySimBytes(const DensityGrid& g) {
  const long long cells = static_cast<long long>(g.n[0]) * g.n[1] * g.n[2];
  return cells * 4 * 4 + 3 * (cells + g.n[0] * g.n[1] + g.n[1] * g.n[2] + g.n[0] * g.n[2]) * 4;
}

DensitySim::DensitySim(const DensitySpec& spec, const DensityGrid& grid, const HazerSchedule& schedule)
    : spec_(spec), grid_(grid), schedule_(schedule) {
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2];
  const DensityField shape = DensityField::filled(nx, ny, nz, grid.minM, grid.maxM, 0.0f);
  h_ = shape.cellSizeM();
  still_.resize(shape.values.size());
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const glm::vec3 p = shape.cellCentre(x, y, z);
        float d = spec.base;
        if (spec.fog) {
          const FogLayerSpec& f = *spec.fog;
          d += p.y <= f.heightM ? f.density : f.density * std::exp(-(p.y - f.heightM) / std::max(f.falloffM, 1e-3f));
        }
        for (const DensityBoxSpec& b : spec.boxes)
          if (glm::all(glm::greaterThanEqual(p, b.minM)) && glm::all(glm::lessThanEqual(p, b.maxM))) d = b.density;
        still_[shape.index(x, y, z)] = std::max(d, 0.0f);
      }

  // The air at the faces: the room's flow plus every fan; the grid's own faces are walls.
  r0_ = std::max(0.5f * std::max({h_.x, h_.y, h_.z}), 0.05f);
  for (const HazerSpec& hz : spec.hazers) {
    const float len = glm::length(hz.direction);
    dirs_.push_back(len > 0.0f ? hz.direction / len : glm::vec3(0.0f, 0.0f, -1.0f));
  }
  std::vector<float> full(spec.hazers.size(), 1.0f);
  if (!schedule_.fansChange()) {
    // Fans held at one level: the air is summed once, at that level.
    for (size_t i = 0; i < full.size(); ++i) full[i] = std::clamp(schedule_.at(i, 0.0).fan, 0.0f, 1.0f);
    fillFaces(full, true, ux_, uy_, uz_);
  } else {
    fillFaces({}, true, roomX_, roomY_, roomZ_);
    fanX_.resize(spec.hazers.size());
    fanY_.resize(spec.hazers.size());
    fanZ_.resize(spec.hazers.size());
    for (size_t i = 0; i < spec.hazers.size(); ++i) {
      std::vector<float> one(spec.hazers.size(), 0.0f);
      one[i] = 1.0f;
      fillFaces(one, false, fanX_[i], fanY_[i], fanZ_[i]);
    }
    // The step must hold at any level in 0..1: the bound |room| + sum |fan| on every face.
    ux_ = roomX_, uy_ = roomY_, uz_ = roomZ_;
    for (float& v : ux_) v = std::fabs(v);
    for (float& v : uy_) v = std::fabs(v);
    for (float& v : uz_) v = std::fabs(v);
    for (size_t i = 0; i < spec.hazers.size(); ++i)
      for (size_t f = 0; f < ux_.size(); ++f) ux_[f] += std::fabs(fanX_[i][f]);
    for (size_t i = 0; i < spec.hazers.size(); ++i)
      for (size_t f = 0; f < uy_.size(); ++f) uy_[f] += std::fabs(fanY_[i][f]);
    for (size_t i = 0; i < spec.hazers.size(); ++i)
      for (size_t f = 0; f < uz_.size(); ++f) uz_[f] += std::fabs(fanZ_[i][f]);
  }

  // The step: every cell's outflow (advection through its faces plus diffusion) below 0.9 of it.
  double rate = 0.0;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const size_t fx = (static_cast<size_t>(z) * ny + y) * (nx + 1) + x;
        const size_t fy = (static_cast<size_t>(z) * (ny + 1) + y) * nx + x;
        const size_t fz = (static_cast<size_t>(z) * ny + y) * nx + x;
        const double a = std::max(std::fabs(ux_[fx]), std::fabs(ux_[fx + 1])) / h_.x +
                         std::max(std::fabs(uy_[fy]), std::fabs(uy_[fy + nx])) / h_.y +
                         std::max(std::fabs(uz_[fz]), std::fabs(uz_[fz + static_cast<size_t>(nx) * ny])) / h_.z;
        rate = std::max(rate, a);
      }
  const double K = std::max(spec.mixingM2ps, 0.0f);
  rate += 2.0 * K * (1.0 / (h_.x * h_.x) + 1.0 / (h_.y * h_.y) + 1.0 / (h_.z * h_.z));
  dt_ = rate > 0.0 ? std::min(kMaxStepS, 0.9 / rate) : kMaxStepS;

  for (size_t i = 0; i < spec.hazers.size(); ++i) {
    // The haze enters the cell just in front of the nozzle.
    const glm::vec3 at = spec.hazers[i].positionM + dirs_[i] * (0.5f * std::min({h_.x, h_.y, h_.z}));
    int c[3];
    for (int k = 0; k < 3; ++k) {
      const float u = (at[k] - grid.minM[k]) / h_[k];
      c[k] = std::clamp(static_cast<int>(std::floor(u)), 0, grid.n[k] - 1);
    }
    sourceCell_.push_back(shape.index(c[0], c[1], c[2]));
  }
  clamped_ = hazersOutside(spec, grid);
  reset();
}

void DensitySim::fillFaces(const std::vector<float>& fanLevels, bool roomAir, std::vector<float>& ux,
                           std::vector<float>& uy, std::vector<float>& uz) const {
  const int nx = grid_.n[0], ny = grid_.n[1], nz = grid_.n[2];
  auto air = [&](const glm::vec3& p) {
    glm::vec3 u = roomAir ? spec_.airFlowMps : glm::vec3(0.0f);
    for (size_t i = 0; i < fanLevels.size(); ++i)
      if (fanLevels[i] > 0.0f) u += fanLevels[i] * fanVelocity(spec_.hazers[i], dirs_[i], r0_, p);
    return u;
  };
  ux.assign(static_cast<size_t>(nx + 1) * ny * nz, 0.0f);
  uy.assign(static_cast<size_t>(nx) * (ny + 1) * nz, 0.0f);
  uz.assign(static_cast<size_t>(nx) * ny * (nz + 1), 0.0f);
  const glm::vec3 o = grid_.minM;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 1; x < nx; ++x)
        ux[(static_cast<size_t>(z) * ny + y) * (nx + 1) + x] = air(o + glm::vec3(x, y + 0.5f, z + 0.5f) * h_).x;
  for (int z = 0; z < nz; ++z)
    for (int y = 1; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        uy[(static_cast<size_t>(z) * (ny + 1) + y) * nx + x] = air(o + glm::vec3(x + 0.5f, y, z + 0.5f) * h_).y;
  for (int z = 1; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        uz[(static_cast<size_t>(z) * ny + y) * nx + x] = air(o + glm::vec3(x + 0.5f, y + 0.5f, z) * h_).z;
}

void DensitySim::setFans(double tS) {
  if (fanX_.empty()) return;  // the fans hold one level: ux_.. were summed once
  std::vector<float> levels(spec_.hazers.size());
  for (size_t i = 0; i < levels.size(); ++i) levels[i] = std::clamp(schedule_.at(i, tS).fan, 0.0f, 1.0f);
  if (levels == fanLevels_) return;
  fanLevels_ = levels;
  ux_ = roomX_, uy_ = roomY_, uz_ = roomZ_;
  for (size_t i = 0; i < levels.size(); ++i) {
    if (levels[i] == 0.0f) continue;
    for (size_t f = 0; f < ux_.size(); ++f) ux_[f] += levels[i] * fanX_[i][f];
    for (size_t f = 0; f < uy_.size(); ++f) uy_[f] += levels[i] * fanY_[i][f];
    for (size_t f = 0; f < uz_.size(); ++f) uz_[f] += levels[i] * fanZ_[i][f];
  }
}

std::vector<int> hazersOutside(const DensitySpec& spec, const DensityGrid& grid) {
  std::vector<int> out;
  for (size_t i = 0; i < spec.hazers.size(); ++i) {
    const glm::vec3 p = spec.hazers[i].positionM;
    bool outside = false;
    for (int k = 0; k < 3; ++k) outside = outside || p[k] < grid.minM[k] || p[k] > grid.maxM[k];
    if (outside) out.push_back(static_cast<int>(i));
  }
  return out;
}

void DensitySim::reset() {
  haze_.assign(still_.size(), 0.0f);
  k_ = 0;
}

void DensitySim::step(std::vector<float>& c, double t0, double dt) {
  const double mid = t0 + 0.5 * dt;
  setFans(mid);
  const int nx = grid_.n[0], ny = grid_.n[1], nz = grid_.n[2];
  scratch_ = c;
  std::vector<float>& out = scratch_;
  const float K = std::max(spec_.mixingM2ps, 0.0f);
  const float ax = static_cast<float>(dt) / h_.x, ay = static_cast<float>(dt) / h_.y, az = static_cast<float>(dt) / h_.z;
  const float kx = K * ax / h_.x, ky = K * ay / h_.y, kz = K * az / h_.z;
  const size_t sx = 1, sy = static_cast<size_t>(nx), sz = static_cast<size_t>(nx) * ny;
  // Through the face between cell a (lower) and cell b = a + stride: advection from the
  // upwind cell, diffusion down the gradient.
  auto face = [&](size_t a, size_t b, float u, float adv, float dif) {
    const float flux = u * adv * (u > 0.0f ? c[a] : c[b]) + dif * (c[a] - c[b]);
    out[a] -= flux;
    out[b] += flux;
  };
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y) {
      const size_t row = static_cast<size_t>(z) * sz + static_cast<size_t>(y) * sy;
      const size_t frow = (static_cast<size_t>(z) * ny + y) * (nx + 1);
      for (int x = 1; x < nx; ++x) face(row + x - 1, row + x, ux_[frow + x], ax, kx);
    }
  for (int z = 0; z < nz; ++z)
    for (int y = 1; y < ny; ++y) {
      const size_t row = static_cast<size_t>(z) * sz + static_cast<size_t>(y) * sy;
      const size_t frow = (static_cast<size_t>(z) * (ny + 1) + y) * nx;
      for (int x = 0; x < nx; ++x) face(row + x - sy, row + x, uy_[frow + x], ay, ky);
    }
  for (int z = 1; z < nz; ++z)
    for (int y = 0; y < ny; ++y) {
      const size_t row = static_cast<size_t>(z) * sz + static_cast<size_t>(y) * sy;
      const size_t frow = (static_cast<size_t>(z) * ny + y) * nx;
      for (int x = 0; x < nx; ++x) face(row + x - sz, row + x, uz_[frow + x], az, kz);
    }
  (void)sx;
  const float volume = h_.x * h_.y * h_.z;
  for (size_t i = 0; i < spec_.hazers.size(); ++i)
    out[sourceCell_[i]] += static_cast<float>(std::max(spec_.hazers[i].output, 0.0f) *
                                              std::clamp(schedule_.at(i, mid).output, 0.0f, 1.0f) * dt / volume);
  if (spec_.dissipationPerS > 0.0f) {
    const float keep = static_cast<float>(std::exp(-double(spec_.dissipationPerS) * dt));
    for (float& v : out) v *= keep;
  }
  c.swap(out);
}

void DensitySim::advanceTo(double tS) {
  const long long target = static_cast<long long>(std::floor(std::max(tS, 0.0) / dt_));
  if (target < k_) reset();
  if (spec_.hazers.empty()) {  // nothing moves: no haze to carry
    k_ = target;
    return;
  }
  for (; k_ < target; ++k_) step(haze_, static_cast<double>(k_) * dt_, dt_);
}

DensityField DensitySim::fieldAt(double tS) {
  advanceTo(tS);
  std::vector<float> haze = haze_;
  const double rest = std::max(tS, 0.0) - static_cast<double>(k_) * dt_;
  if (rest > 1e-9 && !spec_.hazers.empty()) step(haze, static_cast<double>(k_) * dt_, rest);
  DensityField f = DensityField::filled(grid_.n[0], grid_.n[1], grid_.n[2], grid_.minM, grid_.maxM, 0.0f);
  for (size_t i = 0; i < f.values.size(); ++i) f.values[i] = still_[i] + std::max(haze[i], 0.0f);
  return f;
}

double DensitySim::hazeTotalAt(double tS) {
  advanceTo(tS);
  std::vector<float> haze = haze_;
  const double rest = std::max(tS, 0.0) - static_cast<double>(k_) * dt_;
  if (rest > 1e-9 && !spec_.hazers.empty()) step(haze, static_cast<double>(k_) * dt_, rest);
  double sum = 0.0;
  for (float v : haze) sum += v;
  return sum * static_cast<double>(h_.x) * h_.y * h_.z;
}

}  // namespace haze
