// OpenEXR stills: docs/physics.md's radiometric L (cd/m^2 per linear Rec. 709 channel), the same
// numbers as the PFM, in a file compositing and grading tools read directly.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "fixtures/core/result.h"
#include "shows/scene/image.h"

namespace haze {

enum class ExrPixel { Half, Float };

struct ExrOptions {
  ExrPixel pixel = ExrPixel::Half;
  std::string comment;  // the header's "comments" attribute (show, cue list, cue, time)
};

struct ExrWritten {
  // Half only: pixels with a channel above half's largest value (65504), written as 65504
  // instead of infinity. The caller warns, naming how many.
  size_t clampedPixels = 0;
};

// R, G, B channels, ZIP compressed, Rec. 709 chromaticities with D65 white, whiteLuminance 1
// (a value of 1 is 1 cd/m^2). Written through writeFileAtomically: never half a file.
Result<ExrWritten> writeExr(const ImageRGB& image, const std::filesystem::path& file,
                            const ExrOptions& options = {});

// "half" or "float"; anything else is nullopt.
std::optional<ExrPixel> parseExrPixel(const std::string& name);

}  // namespace haze
