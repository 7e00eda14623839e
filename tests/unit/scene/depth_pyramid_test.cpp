// The shadow maps' least-depth pyramid (shows/scene/depth_pyramid.h) must never claim a
// depth greater than one of the texels a texel of it covers: a lookup that trusts it skips its
// shadow taps, so a value too large would light a shadowed point.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "shows/scene/depth_pyramid.h"

namespace haze {
namespace {

// The least depth over the map's texels [i c, (i + 2) c) x [j c, (j + 2) c), the last texel of a
// level reaching to the map's edge: the definition, by brute force.
float coveredMin(const std::vector<float>& depth, int size, int levelSize, int c, int i, int j) {
  auto end = [&](int k) { return k == levelSize - 1 ? size : std::min(size, (k + 2) * c); };
  float v = 1e30f;
  for (int y = j * c; y < end(j); ++y)
    for (int x = i * c; x < end(i); ++x) v = std::min(v, depth[static_cast<size_t>(y) * size + x]);
  return v;
}

void expectPyramidOf(int size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> depth(static_cast<size_t>(size) * size);
  for (float& d : depth) d = u(rng);
  const DepthPyramid p = buildDepthPyramid(depth, size);
  ASSERT_FALSE(p.levels.empty());
  EXPECT_EQ(p.size, (size + 7) / 8);
  EXPECT_EQ(p.levelSize(static_cast<int>(p.levels.size()) - 1), 1);
  for (size_t m = 0; m < p.levels.size(); ++m) {
    const int n = p.levelSize(static_cast<int>(m));
    ASSERT_EQ(p.levels[m].size(), static_cast<size_t>(n) * n);
    const int c = 8 << m;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        ASSERT_EQ(p.levels[m][static_cast<size_t>(j) * n + i], coveredMin(depth, size, n, c, i, j))
            << "size " << size << " level " << m << " texel " << i << "," << j;
  }
}

TEST(DepthPyramid, EachTexelIsTheLeastDepthItCovers) {
  for (int size : {1, 7, 8, 64, 100, 176, 640}) expectPyramidOf(size, static_cast<unsigned>(size));
}

// The lookup of shaders/beams.glsl (surelyLit): any run of texels [lo, hi] no longer than the
// level's cell lies inside the texel it reads.
TEST(DepthPyramid, ARunNoLongerThanACellLiesInOneTexel) {
  for (int size : {100, 640}) {
    const int n0 = (size + 7) / 8;
    for (int lo = 0; lo < size; lo += 3)
      for (int span = 1; lo + span <= size; span = span * 2 + 1) {
        int m = 0;
        while ((8 << m) < span) ++m;
        int levels = 1;
        while ((n0 >> levels) > 0) ++levels;
        m = std::min(m, levels - 1);
        const int c = 8 << m, n = std::max(1, n0 >> m);
        const int t = std::min(lo / c, n - 1);
        const int end = t == n - 1 ? size : (t + 2) * c;
        EXPECT_GE(lo, t * c);
        EXPECT_LE(lo + span, end) << "size " << size << " lo " << lo << " span " << span;
      }
  }
}

}  // namespace
}  // namespace haze
