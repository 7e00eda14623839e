// The density field a show's frames get (docs/shows.md, "Density"): its DensitySpec simulated
// over the venue's bounds to the playback time. Keeps the simulation between calls, so a video
// or a GUI session steps it forward instead of starting over for every frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "atmosphere/density_sim.h"
#include "shows/show.h"

namespace haze {

// The simulation time of playback time clockS: warmup + clockS (warmup alone when still).
double densityTimeS(const DensitySpec& spec, double clockS);
// Whether the field changes with the playback clock (hazers running, not held still).
bool densityMoves(const AtmosphereDef& atmosphere);

// One warning per hazer outside the grid, naming the show file and the hazer's JSON pointer.
std::vector<std::string> hazerWarnings(const Show& show, const DensityGrid& grid);

class AtmosphereField {
 public:
  // The field at playback time clockS, or null when the show has no density (the uniform
  // medium), with the hazers at the levels of `hazers` (shows/hazer_levels.h; empty: full).
  // New warnings (a hazer outside the venue, moved in) are appended once per spec, each naming
  // the show file and the JSON pointer.
  std::shared_ptr<const DensityField> at(const Show& show, const glm::vec3& venueMinM, const glm::vec3& venueMaxM,
                                         double clockS, std::vector<std::string>& warnings,
                                         const HazerSchedule& hazers = {});
  // The field the last call returned (null: none yet, or the uniform medium).
  const std::shared_ptr<const DensityField>& last() const { return last_; }

 private:
  std::unique_ptr<DensitySim> sim_;
  DensitySpec spec_;
  DensityGrid grid_;
  HazerSchedule hazers_;
  double lastTimeS_ = -1.0;
  std::shared_ptr<const DensityField> last_;
};

}  // namespace haze
