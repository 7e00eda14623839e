// The accuracy metric (image_compare.h): mean relative error over the values the reference
// lights, with the leak where it does not.
#include "shows/scene/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace haze {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool sameSize(const ImageRGB& a, const ImageRGB& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size();
}

// The q-quantile of every channel value of the image.
float quantile(const ImageRGB& image, double q) {
  std::vector<float> v;
  v.reserve(image.pixels.size() * 3);
  for (const glm::vec3& p : image.pixels) v.insert(v.end(), {p.r, p.g, p.b});
  if (v.empty()) return 0.0f;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

Result<BeamComparison> compareBeams(const ImageRGB& actual, const ImageRGB& reference) {
  if (!sameSize(actual, reference))
    return Error{"", "", "the image is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                             " but the reference is " + std::to_string(reference.width) + "x" +
                             std::to_string(reference.height)};
  float inMax = 0.0f;
  for (const glm::vec3& p : reference.pixels) inMax = std::max({inMax, p.r, p.g, p.b});
  if (!(inMax > 0.0f)) return Error{"", "", "the reference has no in-scattered light: nothing was compared"};
  const float p999 = quantile(reference, 0.999);
  const float coreCut = 0.01f * inMax, wideCut = 0.01f * p999, darkCut = 0.001f * p999;
  BeamComparison c;
  double core = 0.0, wide = 0.0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const float r = reference.pixels[i][ch], a = actual.pixels[i][ch];
      if (r > wideCut) {
        const double e = std::abs(double(a) - r) / r;
        wide += e;
        ++c.wideValues;
        if (e > 0.5) ++c.grossValues;
        if (r > coreCut) {
          core += e;
          ++c.coreValues;
        }
      } else if (r < darkCut) {
        ++c.darkValues;
        if (a > wideCut) ++c.leakedValues;
      }
    }
  if (c.coreValues > 0) c.coreError = core / double(c.coreValues);
  if (c.wideValues > 0) c.wideError = wide / double(c.wideValues);
  return c;
}

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
