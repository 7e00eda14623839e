// The accuracy metric, in its one copy: how far a radiometric image is from a reference (the
// renderer against the CPU integrator). `haze compare`, `haze bench` and the render tests all
// call this, so the number a test asserts on is the number a user reads.
#pragma once

#include <cstddef>

#include "fixtures/core/result.h"
#include "shows/scene/image.h"

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

// The metric for the beams (docs/rendering.md, "Accuracy"), on in-scattered radiance L_in
// alone, so that neither a bright floor pool nor a lamp's lens disc in frame (millions of
// cd/m^2) can hide the haze: the mean relative error of L_in over the beam cores (values above
// 1 % of the reference's largest L_in) and over the wider mask (above 1 % of its 99.9th
// percentile over every channel of every pixel, which a lamp's few brightest pixels cannot
// move), and the leak: of the values the reference leaves dark (below 0.1 % of that
// percentile), the fraction the image lights above 1 % of it.
struct BeamComparison {
  double coreError = 0, wideError = 0;
  size_t coreValues = 0, wideValues = 0;
  size_t darkValues = 0, leakedValues = 0;
  // Wide-mask values off by more than half: what a mean hides when a small beam is missing or
  // misplaced beside a large one (its own pixels are all wrong, the mean barely moves).
  size_t grossValues = 0;
  double leak() const { return darkValues > 0 ? double(leakedValues) / double(darkValues) : 0.0; }
  double gross() const { return wideValues > 0 ? double(grossValues) / double(wideValues) : 0.0; }
};
// An error when the sizes differ or when the reference has no in-scattered light.
Result<BeamComparison> compareBeams(const ImageRGB& actualInScattered, const ImageRGB& referenceInScattered);

}  // namespace haze
