// The accuracy metric (image_compare.h): mean relative error over the values the reference
// lights, with the leak where it does not.
#include "renderer/scene/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace haze {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

Result<ImageComparison> compareImages(const ImageRGB& actual, const ImageRGB& reference, float threshold) {
  if (actual.width != reference.width || actual.height != reference.height ||
      actual.pixels.size() != reference.pixels.size())
    return Error{"", "", "the image is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                             " but the reference is " + std::to_string(reference.width) + "x" +
                             std::to_string(reference.height)};
  ImageComparison c;
  for (const glm::vec3& p : reference.pixels) c.referenceMax = std::max({c.referenceMax, p.r, p.g, p.b});
  const float cut = threshold * c.referenceMax;
  double sum = 0.0, leakSum = 0.0;
  size_t dark = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const float r = reference.pixels[i][ch], a = actual.pixels[i][ch];
      if (r > cut) {
        // Divided in float, summed in double: the published numbers were computed so.
        const double e = std::abs(a - r) / r;
        sum += e;
        c.maxRelError = std::max(c.maxRelError, e);
        ++c.values;
      } else {
        leakSum += std::abs(a - r);
        ++dark;
      }
    }
  if (c.values == 0)
    return Error{"", "", "no value of the reference is above " + number(threshold) + " of its maximum (" +
                             number(c.referenceMax) + "): nothing was compared"};
  c.meanRelError = sum / static_cast<double>(c.values);
  if (dark > 0 && c.referenceMax > 0) c.leak = leakSum / static_cast<double>(dark) / c.referenceMax;
  return c;
}

}  // namespace haze
