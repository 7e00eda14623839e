// The grid field: trilinear between cell centres, the edge cells' value outside, and its line
// integral against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "atmosphere/density_field.h"

namespace haze {
namespace {

TEST(DensityField, OneEverywhereIsExactlyOneAndItsIntegralIsTheLength) {
  const DensityField f = DensityField::filled(8, 5, 7, {-3, 0, -2}, {5, 4, 6}, 1.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 p(-6.0f + 0.071f * i, -1.0f + 0.033f * i, 8.0f - 0.09f * i);  // inside and outside
    EXPECT_EQ(f.sample(p), 1.0f);
  }
  const glm::vec3 a(-4, 0.5f, 7), b(6, 3.5f, -3);
  EXPECT_NEAR(f.integral(a, b), glm::length(b - a), 1e-5 * glm::length(b - a));
  // An empty field is the uniform medium too.
  EXPECT_EQ(DensityField{}.sample(a), 1.0f);
  EXPECT_FLOAT_EQ(DensityField{}.integral(a, b), glm::length(b - a));
}

TEST(DensityField, TrilinearBetweenCentresAndClampedOutside) {
  // D = 2 + x on the cell centres of 10 cells over x in [0, 10]: centres at 0.5 .. 9.5.
  DensityField f = DensityField::filled(10, 2, 2, {0, 0, 0}, {10, 1, 1}, 0.0f);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 10; ++x) f.values[f.index(x, y, z)] = 2.0f + f.cellCentre(x, y, z).x;
  EXPECT_NEAR(f.sample({3.3f, 0.5f, 0.5f}), 5.3f, 1e-5f);
  EXPECT_NEAR(f.sample({0.1f, 0.5f, 0.5f}), 2.5f, 1e-5f);   // below the first centre: its value
  EXPECT_NEAR(f.sample({12.0f, 0.5f, 0.5f}), 11.5f, 1e-5f); // beyond the grid: the edge cell's
  // The integral of 2 + x from x = 1 to 9 along a line is 8 * 2 + (81 - 1) / 2 = 56.
  EXPECT_NEAR(f.integral({1, 0.3f, 0.7f}, {9, 0.3f, 0.7f}), 56.0f, 1e-3f);
}

// The Air tab's slice: D = y + 10 x + 100 z on the cell centres (linear, so trilinear is exact
// between them) read back on a plane between two layers of centres.
TEST(DensityField, AHorizontalSliceIsTheFieldAtTheCellCentresOfThatHeight) {
  DensityField f = DensityField::filled(3, 4, 2, {0, 0, 0}, {3, 4, 2}, 0.0f);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 3; ++x) {
        const glm::vec3 c = f.cellCentre(x, y, z);
        f.values[f.index(x, y, z)] = c.y + 10.0f * c.x + 100.0f * c.z;
      }
  const std::vector<float> s = f.horizontalSlice(1.8f);
  ASSERT_EQ(s.size(), 6u);
  for (int z = 0; z < 2; ++z)
    for (int x = 0; x < 3; ++x)
      EXPECT_NEAR(s[static_cast<size_t>(z * 3 + x)], 1.8f + 10.0f * (x + 0.5f) + 100.0f * (z + 0.5f), 1e-4f) << x << " " << z;
  EXPECT_TRUE(DensityField{}.horizontalSlice(1.0f).empty());
}

}  // namespace
}  // namespace haze
