#include "shows/scene/draft_scale.h"

#include <algorithm>
#include <cmath>

namespace haze {

namespace {
// Scales are multiples of this: the renderer's targets are remade on each change, so the scale
// moves in steps, not every frame by a little.
constexpr float kStep = 1.0f / 16.0f;
// Frames between 70 % and 100 % of the budget keep their scale: the dead band stops a scale that
// sits at the edge from flipping every frame.
constexpr double kLow = 0.7;
}  // namespace

DraftScale::DraftScale(double budgetMs, float minScale) : budgetMs_(budgetMs), minScale_(minScale) {}

void DraftScale::setBudget(double budgetMs) {
  budgetMs_ = budgetMs;
  scale_ = 1.0f;
  limited_ = false;
}

float DraftScale::update(double frameMs) {
  if (budgetMs_ <= 0.0 || !(frameMs > 0.0)) {
    limited_ = false;
    if (budgetMs_ <= 0.0) scale_ = 1.0f;
    return scale_;
  }
  const double ratio = budgetMs_ / frameMs;
  if (ratio >= 1.0 && ratio <= 1.0 / kLow) return scale_;
  // Cost taken as proportional to pixels, the area follows the ratio; a step is at most a
  // halving or a doubling of the area, since part of a frame's cost is not per pixel.
  const double wanted = scale_ * std::sqrt(std::clamp(ratio, 0.5, 2.0));
  float next = static_cast<float>(ratio < 1.0 ? std::floor(wanted / kStep) : std::floor(wanted / kStep + 0.5)) * kStep;
  if (ratio < 1.0) next = std::min(next, scale_ - kStep);  // a slow frame always shrinks the next
  limited_ = ratio < 1.0 && next < minScale_;
  scale_ = std::clamp(next, minScale_, 1.0f);
  return scale_;
}

}  // namespace haze
