#include "atmosphere/density_field.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace haze {

DensityField DensityField::filled(int nx, int ny, int nz, glm::vec3 minM, glm::vec3 maxM, float value) {
  DensityField f;
  f.nx = nx;
  f.ny = ny;
  f.nz = nz;
  f.minM = minM;
  f.maxM = maxM;
  f.values.assign(static_cast<size_t>(nx) * ny * nz, value);
  return f;
}

glm::vec3 DensityField::cellSizeM() const {
  return (maxM - minM) / glm::vec3(static_cast<float>(nx), static_cast<float>(ny), static_cast<float>(nz));
}

glm::vec3 DensityField::cellCentre(int x, int y, int z) const {
  return minM + (glm::vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)) + 0.5f) * cellSizeM();
}

float DensityField::cellVolumeM3() const {
  const glm::vec3 c = cellSizeM();
  return c.x * c.y * c.z;
}

float DensityField::sample(const glm::vec3& p) const {
  if (values.empty()) return 1.0f;
  // Continuous cell coordinates with centres at integers, clamped to the edge cells' centres.
  const glm::vec3 size = maxM - minM;
  float c[3];
  int i0[3], i1[3];
  float f[3];
  const int n[3] = {nx, ny, nz};
  for (int k = 0; k < 3; ++k) {
    const float u = size[k] > 0.0f ? (p[k] - minM[k]) / size[k] * static_cast<float>(n[k]) - 0.5f : 0.0f;
    c[k] = std::clamp(u, 0.0f, static_cast<float>(n[k] - 1));
    i0[k] = std::min(static_cast<int>(c[k]), n[k] - 1);
    i1[k] = std::min(i0[k] + 1, n[k] - 1);
    f[k] = c[k] - static_cast<float>(i0[k]);
  }
  auto v = [&](int x, int y, int z) { return values[index(x, y, z)]; };
  const float x00 = v(i0[0], i0[1], i0[2]) + f[0] * (v(i1[0], i0[1], i0[2]) - v(i0[0], i0[1], i0[2]));
  const float x10 = v(i0[0], i1[1], i0[2]) + f[0] * (v(i1[0], i1[1], i0[2]) - v(i0[0], i1[1], i0[2]));
  const float x01 = v(i0[0], i0[1], i1[2]) + f[0] * (v(i1[0], i0[1], i1[2]) - v(i0[0], i0[1], i1[2]));
  const float x11 = v(i0[0], i1[1], i1[2]) + f[0] * (v(i1[0], i1[1], i1[2]) - v(i0[0], i1[1], i1[2]));
  const float y0 = x00 + f[1] * (x10 - x00);
  const float y1 = x01 + f[1] * (x11 - x01);
  return y0 + f[2] * (y1 - y0);
}

float DensityField::integralStepM() const {
  const glm::vec3 c = cellSizeM();
  return 0.25f * std::max(std::min({c.x, c.y, c.z}), 1e-4f);
}

float DensityField::integral(const glm::vec3& a, const glm::vec3& b) const {
  const float len = glm::length(b - a);
  if (!(len > 0.0f)) return 0.0f;
  if (values.empty()) return len;
  const int n = std::max(1, static_cast<int>(std::ceil(len / integralStepM())));
  const glm::vec3 step = (b - a) / static_cast<float>(n);
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += sample(a + (static_cast<float>(k) + 0.5f) * step);
  return static_cast<float>(sum * len / n);
}

float DensityField::maxValue() const {
  return values.empty() ? 1.0f : *std::max_element(values.begin(), values.end());
}

std::vector<float> DensityField::horizontalSlice(float yM) const {
  std::vector<float> out;
  if (values.empty()) return out;
  out.reserve(static_cast<size_t>(nx) * static_cast<size_t>(nz));
  for (int z = 0; z < nz; ++z)
    for (int x = 0; x < nx; ++x) {
      const glm::vec3 c = cellCentre(x, 0, z);
      out.push_back(sample({c.x, yM, c.z}));
    }
  return out;
}

}  // namespace haze
