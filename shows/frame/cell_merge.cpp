// Merging a fixture's cells (see cell_merge.h).
#include "shows/frame/cell_merge.h"

#include <algorithm>
#include <map>

#include <glm/geometric.hpp>

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

}  // namespace haze
