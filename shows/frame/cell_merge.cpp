// Merging a fixture's cells (see cell_merge.h).
#include "shows/frame/cell_merge.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "shows/frame/frame_builder.h"

namespace haze {

void mergeCellBeams(std::vector<BeamState>& beams) {
  if (beams.size() < 2) return;
  std::map<uint64_t, std::vector<size_t>> groups;
  for (size_t i = 0; i < beams.size(); ++i) groups[beams[i].opticsKey].push_back(i);
  std::vector<BeamState> out;
  for (const auto& [key, members] : groups) {
    BeamState merged = beams[members.front()];
    if (members.size() > 1) {
      glm::vec3 light(0.0f), centre(0.0f), plain(0.0f);
      float weight = 0.0f;
      for (size_t i : members) {
        const BeamState& b = beams[i];
        const glm::vec3 l = b.optics.dimmer * b.optics.color;
        const float w = l.r + l.g + l.b;
        light += l;
        centre += w * b.pose.lensPosition;
        plain += b.pose.lensPosition;
        weight += w;
      }
      centre = weight > 0.0f ? centre / weight : plain / static_cast<float>(members.size());
      float radius = 0.0f;
      for (size_t i : members)
        radius = std::max(radius, glm::length(beams[i].pose.lensPosition - centre) + beams[i].optics.lensRadiusM);
      const float peak = std::max({light.r, light.g, light.b});
      merged.optics.dimmer = peak;
      merged.optics.color = peak > 0.0f ? light / peak : glm::vec3(1.0f);
      merged.optics.lensRadiusM = radius;
      merged.pose.lensPosition = centre;
      merged.poseKey = poseCacheKey(merged.pose);
      merged.cell = -1;  // several cells
    }
    out.push_back(std::move(merged));
  }
  beams = std::move(out);
}

bool cellsActAsOne(const std::vector<BeamState>& beams, size_t cells) {
  if (beams.size() < 2 || beams.size() != cells) return false;
  const BeamState& first = beams.front();
  glm::vec3 centre(0.0f);
  for (const BeamState& b : beams) {
    if (b.cell < 0 || b.opticsKey != first.opticsKey) return false;
    // Alike to a thousandth of the level, finer than one step of 8-bit DMX (1/255).
    const float tolerance = 1e-3f * std::max(first.optics.dimmer, b.optics.dimmer);
    if (std::abs(b.optics.dimmer - first.optics.dimmer) > tolerance) return false;
    for (int c = 0; c < 3; ++c)
      if (std::abs(b.optics.color[c] - first.optics.color[c]) > 1e-3f) return false;
    centre += b.pose.lensPosition;
  }
  centre /= static_cast<float>(beams.size());
  float spread = 0.0f;
  for (const BeamState& b : beams) spread = std::max(spread, glm::length(b.pose.lensPosition - centre));
  const float halfField = 0.5f * glm::radians(std::clamp(first.optics.fieldAngleDeg, 0.0f, 179.0f));
  return spread <= std::tan(halfField) * kCellsOverlapWithinM;
}

}  // namespace haze
