// The frames of an image sequence that several processes share (docs/output.md, "Rendering on a
// cluster"): whether a frame file on disk is a whole image, for `--resume` and `haze farm status`,
// and reading a PNG frame back for `haze farm encode`. Decoding the whole file is the check: a
// file cut short (a node that died while copying, a full disk) fails to decode and is redone.
#pragma once

#include <filesystem>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

// A PNG that decodes to the end and closes with its IEND chunk, or an EXR whose every scan line
// reads; false for anything else, a missing file included.
bool frameFileComplete(const std::filesystem::path& file);

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // row 0 at the top, 3 bytes a pixel
};

// An 8-bit PNG as RGB (grey or alpha are converted); the error names the file.
Result<Rgb8Image> readPngRgb8(const std::filesystem::path& file);

}  // namespace haze
