#include "shows/scene/depth_pyramid.h"

#include <algorithm>
#include <cstddef>

namespace haze {

DepthPyramid buildDepthPyramid(const std::vector<float>& depth, int size) {
  DepthPyramid p;
  if (size <= 0 || depth.size() < static_cast<size_t>(size) * size) return p;
  const int first = 1 << kDepthPyramidFirstShift;
  p.size = (size + first - 1) / first;
  // blocks: the least depth over disjoint cells of c x c texels (ceil(size / c) per side).
  int nb = p.size;
  std::vector<float> blocks(static_cast<size_t>(nb) * nb, 1e30f);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float& b = blocks[static_cast<size_t>(y / first) * nb + x / first];
      b = std::min(b, depth[static_cast<size_t>(y) * size + x]);
    }
  for (int m = 0;; ++m) {
    const int n = p.levelSize(m);
    // Texel i covers blocks [i, i + 1], the last texel every block from i on.
    auto span = [&](int i) { return std::pair{i, i == n - 1 ? nb - 1 : std::min(i + 1, nb - 1)}; };
    std::vector<float> level(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j) {
      const auto [j0, j1] = span(j);
      for (int i = 0; i < n; ++i) {
        const auto [i0, i1] = span(i);
        float v = 1e30f;
        for (int bj = j0; bj <= j1; ++bj)
          for (int bi = i0; bi <= i1; ++bi) v = std::min(v, blocks[static_cast<size_t>(bj) * nb + bi]);
        level[static_cast<size_t>(j) * n + i] = v;
      }
    }
    p.levels.push_back(std::move(level));
    if (n == 1) break;
    // The next level's blocks: cells twice as wide.
    const int nb2 = (nb + 1) / 2;
    std::vector<float> next(static_cast<size_t>(nb2) * nb2, 1e30f);
    for (int y = 0; y < nb; ++y)
      for (int x = 0; x < nb; ++x) {
        float& b = next[static_cast<size_t>(y / 2) * nb2 + x / 2];
        b = std::min(b, blocks[static_cast<size_t>(y) * nb + x]);
      }
    blocks = std::move(next);
    nb = nb2;
  }
  return p;
}

}  // namespace haze
