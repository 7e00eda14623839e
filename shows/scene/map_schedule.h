// The policy of map work spread over frames (docs/rendering.md, "Map work spread over
// frames"), apart from the GL that does the work: which deferred light-map bakes and shadow-map
// draws go this frame, in which order, and when the frame's budget stops them. Pure: the clock
// and the work are passed in, so the policy is unit-tested with a clock the test controls.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace haze {

enum class MapKind : int { Light = 0, Shadow = 1 };

struct MapJob {
  uint64_t staleSince = 0;  // the update since which the beam's map has been out of date
  int beam = 0;
  MapKind kind = MapKind::Light;
};

class MapSchedule {
 public:
  // Runs `jobs` the longest-waiting first (then by beam, a light map before its shadow map).
  // The first always goes, so that every frame makes progress; each next one while the time
  // spent since the frame began (elapsedMs()) plus the last measured time of its kind still
  // fits budgetMs, so that one map more never overruns the budget by a whole map. `work` returns
  // false when the job has become unnecessary (another beam baked the same light map): it then
  // costs nothing and measures nothing. Returns how many jobs did work.
  int run(std::vector<MapJob> jobs, double budgetMs, const std::function<double()>& elapsedMs,
          const std::function<bool(const MapJob&)>& work);

  // The last measured time of a job of this kind (0 before the first).
  double lastMs(MapKind kind) const { return lastMs_[static_cast<int>(kind)]; }

 private:
  double lastMs_[2] = {0.0, 0.0};
};

}  // namespace haze
