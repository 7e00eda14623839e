// A density field D(x) on a regular grid (docs/physics.md, "A medium that is not uniform"):
// one value per cell, D between cell centres trilinear, and outside the grid the nearest edge
// cell's value (what a GL 3D texture with CLAMP_TO_EDGE gives, so both renderers see one field).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

namespace haze {

struct DensityField {
  int nx = 0, ny = 0, nz = 0;
  glm::vec3 minM{0.0f}, maxM{0.0f};
  std::vector<float> values;  // x fastest, then y, then z

  // A grid of n cells over [minM, maxM], every cell `value`.
  static DensityField filled(int nx, int ny, int nz, glm::vec3 minM, glm::vec3 maxM, float value);

  bool empty() const { return values.empty(); }
  size_t index(int x, int y, int z) const {
    return (static_cast<size_t>(z) * static_cast<size_t>(ny) + static_cast<size_t>(y)) * static_cast<size_t>(nx) +
           static_cast<size_t>(x);
  }
  glm::vec3 cellSizeM() const;
  glm::vec3 cellCentre(int x, int y, int z) const;
  float cellVolumeM3() const;
  // D at a world point.
  float sample(const glm::vec3& x) const;
  // The integral of D along the segment a -> b [m] (so an optical depth is sigma_t times it),
  // by the midpoint rule in steps of a quarter of the smallest cell (D is piecewise trilinear).
  float integral(const glm::vec3& a, const glm::vec3& b) const;
  float integralStepM() const;
  float maxValue() const;
  // D on the horizontal plane y = yM at the grid's cell centres in x and z: nx * nz values, x
  // fastest, row 0 at the lowest z (the Air tab's slice view).
  std::vector<float> horizontalSlice(float yM) const;
};

}  // namespace haze
