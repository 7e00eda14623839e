#include "shows/frame/atmosphere_field.h"

#include <algorithm>
#include <cstdio>

namespace haze {

double densityTimeS(const DensitySpec& spec, double clockS) {
  return spec.warmupS + (spec.still ? 0.0 : std::max(clockS, 0.0));
}

bool densityMoves(const AtmosphereDef& atmosphere) {
  return atmosphere.density && !atmosphere.density->still && !atmosphere.density->hazers.empty();
}

std::vector<std::string> hazerWarnings(const Show& show, const DensityGrid& grid) {
  std::vector<std::string> warnings;
  if (!show.atmosphere.density) return warnings;
  const DensitySpec& spec = *show.atmosphere.density;
  for (int i : hazersOutside(spec, grid)) {
    const glm::vec3 p = spec.hazers[static_cast<size_t>(i)].positionM;
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s: /atmosphere/density/hazers/%d/position: the hazer at [%g, %g, %g] is outside the density "
                  "grid [%g, %g, %g]..[%g, %g, %g] (%s); its haze enters at the nearest cell inside",
                  show.file.string().c_str(), i, p.x, p.y, p.z, grid.minM.x, grid.minM.y, grid.minM.z, grid.maxM.x,
                  grid.maxM.y, grid.maxM.z, spec.boundsMinM || spec.boundsMaxM ? "the density's bounds" : "the venue's bounds");
    warnings.emplace_back(text);
  }
  return warnings;
}

std::shared_ptr<const DensityField> AtmosphereField::at(const Show& show, const glm::vec3& venueMinM,
                                                        const glm::vec3& venueMaxM, double clockS,
                                                        std::vector<std::string>& warnings,
                                                        const HazerSchedule& hazers) {
  if (!show.atmosphere.density) {
    sim_.reset();
    last_.reset();
    return nullptr;
  }
  const DensitySpec& spec = *show.atmosphere.density;
  const DensityGrid grid = densityGrid(spec, venueMinM, venueMaxM);
  const bool same = sim_ && spec == spec_ && grid.minM == grid_.minM && grid.maxM == grid_.maxM &&
                    grid.n[0] == grid_.n[0] && grid.n[1] == grid_.n[1] && grid.n[2] == grid_.n[2];
  if (!same || !(hazers == hazers_)) {
    sim_ = std::make_unique<DensitySim>(spec, grid, hazers);
    hazers_ = hazers;
    last_.reset();
  }
  if (!same) {
    spec_ = spec;
    grid_ = grid;
    for (std::string& w : hazerWarnings(show, grid)) warnings.push_back(std::move(w));
  }
  const double t = densityTimeS(spec, clockS);
  if (!last_ || t != lastTimeS_) {
    last_ = std::make_shared<const DensityField>(sim_->fieldAt(t));
    lastTimeS_ = t;
  }
  return last_;
}

}  // namespace haze
