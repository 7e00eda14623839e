#include "shows/scene/map_schedule.h"

#include <algorithm>
#include <tuple>

namespace haze {

int MapSchedule::run(std::vector<MapJob> jobs, double budgetMs, const std::function<double()>& elapsedMs,
                     const std::function<bool(const MapJob&)>& work) {
  std::sort(jobs.begin(), jobs.end(), [](const MapJob& a, const MapJob& b) {
    return std::tie(a.staleSince, a.beam, a.kind) < std::tie(b.staleSince, b.beam, b.kind);
  });
  int done = 0;
  for (const MapJob& job : jobs) {
    const double startMs = elapsedMs();
    double& last = lastMs_[static_cast<int>(job.kind)];
    if (done > 0 && startMs + last > budgetMs) break;
    if (!work(job)) continue;
    last = elapsedMs() - startMs;
    ++done;
  }
  return done;
}

}  // namespace haze
