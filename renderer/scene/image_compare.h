// The accuracy metric, in its one copy: how far a radiometric image is from a reference (the
// renderer against the CPU integrator). `haze compare`, `haze bench` and the render tests all
// call this, so the number a test asserts on is the number a user reads.
#pragma once

#include <cstddef>

#include "fixtures/core/result.h"
#include "renderer/scene/image.h"

namespace haze {

// Each colour channel of each pixel is a value; a value counts when the reference's is above
// threshold * the reference's largest value (any channel, any pixel). docs/physics.md "Accuracy"
// masks on the in-scattered radiance L_in instead; this masks on the total L per channel
// because every number in docs/rendering.md and every test tolerance was measured that way.
struct ImageComparison {
  double meanRelError = 0;  // mean of |actual - reference| / reference over the values that count
  double maxRelError = 0;
  size_t values = 0;        // values that counted (up to 3 per pixel)
  float referenceMax = 0;   // the largest value of the reference, what the threshold scales
  // Light where the reference has (almost) none, which the relative error cannot see: the mean
  // of |actual - reference| over the values that did not count, as a fraction of referenceMax.
  double leak = 0;
};

// An error when the sizes differ or when no value counted (a dark or all-below-threshold
// reference): a mean over nothing would read as a perfect match. Error::file is left empty for
// the caller, who knows the files.
Result<ImageComparison> compareImages(const ImageRGB& actual, const ImageRGB& reference,
                                      float threshold = 0.01f);

}  // namespace haze
