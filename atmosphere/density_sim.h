// The density field of a DensitySpec at a time (docs/physics.md, "A medium that is not
// uniform"; docs/shows.md, "Density"): D = the still part (base, ground fog, boxes) plus the
// hazers' haze, which an advection-diffusion on the grid moves with the room's air and the
// hazers' fans. Deterministic: the same spec and time give the same field, however the time
// was reached (fixed steps from 0; a partial last step on a copy).
#pragma once

#include <string>
#include <vector>

#include "atmosphere/density_field.h"
#include "atmosphere/density_spec.h"
#include "atmosphere/hazer_schedule.h"

namespace haze {

// The grid's box and size a spec asks for; the venue's bounds where the spec gives none.
struct DensityGrid {
  int n[3] = {0, 0, 0};
  glm::vec3 minM{0.0f}, maxM{0.0f};
};
DensityGrid densityGrid(const DensitySpec& spec, const glm::vec3& venueMinM, const glm::vec3& venueMaxM);

// The hazers (their indices in spec.hazers) standing outside the grid's box.
std::vector<int> hazersOutside(const DensitySpec& spec, const DensityGrid& grid);

// Bytes the simulation of a grid holds (the field, its step scratch and three face velocities).
long long densitySimBytes(const DensityGrid& grid);

class DensitySim {
 public:
  // Hazers outside the grid are moved to its nearest inside point (a warning is the caller's,
  // hazersClamped() says which); the grid must be checked against the limits before. The
  // schedule says how hard each hazer and its fan run at each simulation time (none: full).
  DensitySim(const DensitySpec& spec, const DensityGrid& grid, const HazerSchedule& schedule = {});

  // The field at simulation time t >= 0 (seconds the hazers have run). Going back in time
  // starts over from 0.
  DensityField fieldAt(double tS);
  // The hazers' haze alone at time t, as m^3 at D = 1 summed over the grid.
  double hazeTotalAt(double tS);

  double stepS() const { return dt_; }
  const std::vector<int>& hazersClamped() const { return clamped_; }

 private:
  void reset();
  void advanceTo(double tS);
  // One step of dt from time t0: sources and fans at their levels at t0 + dt / 2.
  void step(std::vector<float>& c, double t0, double dt);
  void fillFaces(const std::vector<float>& fanLevels, bool roomAir, std::vector<float>& ux, std::vector<float>& uy,
                 std::vector<float>& uz) const;
  void setFans(double tS);

  DensitySpec spec_;
  DensityGrid grid_;
  glm::vec3 h_{0.0f};
  double dt_ = 0.1;
  std::vector<float> still_;           // base, fog and boxes per cell
  std::vector<float> haze_;            // the hazers' haze per cell, at step k_
  mutable std::vector<float> scratch_;
  HazerSchedule schedule_;
  std::vector<glm::vec3> dirs_;        // per hazer, unit
  float r0_ = 0.05f;                   // the jets' radius at the nozzle
  std::vector<float> ux_, uy_, uz_;    // air speed at the cell faces (x faces: (nx + 1) ny nz)
  // When fans change over time: the room's air and each fan at full speed, which ux_.. are
  // summed from at the levels of each step (fanLevels_ the levels they hold now).
  std::vector<float> roomX_, roomY_, roomZ_;
  std::vector<std::vector<float>> fanX_, fanY_, fanZ_;
  std::vector<float> fanLevels_;
  std::vector<size_t> sourceCell_;     // per hazer
  std::vector<int> clamped_;
  long long k_ = 0;                    // steps done
};

}  // namespace haze
