// haze compare IMAGE.pfm REFERENCE.pfm [--threshold F] [--max-error E] [--json]: the accuracy
// metric of shows/scene/image_compare.h on two PFMs, so shell tests and users read the very
// number the render tests assert on and `haze bench --compare-reference` reports.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "app/command_line.h"
#include "app/commands.h"
#include "shows/scene/image.h"
#include "shows/scene/image_compare.h"

namespace haze {
namespace {

constexpr const char* kUsage =
    "usage: haze compare IMAGE.pfm REFERENCE.pfm [--threshold F] [--max-error E] [--json]\n"
    "Mean relative error |image - reference| / reference over the values (each channel of each pixel)\n"
    "where the reference is above F (default 0.01) times its maximum; also the largest relative error\n"
    "and the leak (mean |image - reference| where the reference is below that, over its maximum).\n"
    "Exit 0; 1 for an unreadable or mismatched file or when no value was compared; 3 when the mean\n"
    "relative error is above --max-error E.\n";

int fail(const std::string& line) {
  std::fprintf(stderr, "haze compare: %s\n", line.c_str());
  return 1;
}

}  // namespace

int runCompare(const Args& args) {
  std::string imagePath, referencePath;
  double threshold = 0.01, maxError = -1.0;  // < 0: no limit
  bool json = false;
  CommandLine cli("haze compare", kUsage);
  cli.number("--threshold", threshold, 0.0, 0.999999, "a fraction of the reference's maximum, 0 <= F < 1")
      .number("--max-error", maxError, 0.0, 1e9, "a mean relative error >= 0")
      .flag("--json", json)
      .positional(imagePath, "image")
      .positional(referencePath, "reference");
  if (auto done = cli.parse(args)) return *done;
  if (referencePath.empty()) return fail("expected IMAGE.pfm REFERENCE.pfm (see haze compare --help)");
  auto image = readPfm(imagePath);
  if (!image) return fail(image.error().str());
  auto reference = readPfm(referencePath);
  if (!reference) return fail(reference.error().str());
  // Checked here as well as in compareImages so that the line names both files.
  if (image->width != reference->width || image->height != reference->height)
    return fail(imagePath + ": " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                " pixels, but the reference " + referencePath + " has " + std::to_string(reference->width) +
                "x" + std::to_string(reference->height));
  auto c = compareImages(*image, *reference, static_cast<float>(threshold));
  if (!c) return fail(referencePath + ": " + c.error().message);
  const bool within = maxError < 0.0 || c->meanRelError <= maxError;
  if (json) {
    nlohmann::ordered_json out;
    out["image"] = imagePath;
    out["reference"] = referencePath;
    out["threshold"] = threshold;
    out["mean_relative_error"] = c->meanRelError;
    out["max_relative_error"] = c->maxRelError;
    out["values_compared"] = c->values;
    out["reference_max"] = c->referenceMax;
    out["leak"] = c->leak;
    if (maxError >= 0.0) {
      out["max_error"] = maxError;
      out["within_max_error"] = within;
    }
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("mean relative error %.6f over %zu values above %g of the reference's maximum %g "
                "(largest %.4f; leak %.6f)\n", c->meanRelError, c->values, threshold, c->referenceMax,
                c->maxRelError, c->leak);
  }
  if (!within) {
    std::fprintf(stderr, "haze compare: %s: mean relative error %.6f is above --max-error %g\n", imagePath.c_str(),
                 c->meanRelError, maxError);
    return 3;
  }
  return 0;
}

}  // namespace haze
