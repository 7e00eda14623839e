// The least depth over blocks of a square depth map, at coarser and coarser levels: a shader
// that must know whether any of the texels a lookup could read lies nearer than a point can
// ask one texel of it instead of reading them all (the shadow maps' "surely lit" test,
// docs/rendering.md, "Soft shadows").
#pragma once

#include <vector>

namespace haze {

// Level m has cells of 2^(kDepthPyramidFirstShift + m) map texels per side and
// max(1, (ceil(size / 2^kDepthPyramidFirstShift)) >> m) texels per side (the GL's mip sizes of its
// level 0). Its texel i (per axis) holds the least depth over the map's texels
// [i c, (i + 2) c), c the cell, two cells so that any run of at most c texels lies inside one
// texel; the last texel reaches to the map's edge. The finest level starts at cells of 8
// texels: a lookup reads at least a 4x4-texel neighbourhood, and the pyramid stays 1/48 of the map.
inline constexpr int kDepthPyramidFirstShift = 3;  // shaders/interface.h: HAZE_SHADOW_MIN_FIRST_SHIFT

struct DepthPyramid {
  int size = 0;                           // texels per side of level 0
  std::vector<std::vector<float>> levels; // row-major, levels[m].size() = n_m^2
  int levelSize(int m) const { return size >> m > 0 ? size >> m : 1; }
};

// depth: size x size, row-major (the GL's rows; the order does not matter to a min).
DepthPyramid buildDepthPyramid(const std::vector<float>& depth, int size);

}  // namespace haze
