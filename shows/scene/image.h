// Float images (radiometric output) and their files: PFM for tests and accuracy work, PNG for
// display after exposure, tone curve and sRGB.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "fixtures/core/result.h"

namespace haze {

struct ImageRGB {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> pixels;  // row 0 = the top row of the picture
  glm::vec3& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// Written to a temporary name beside the target, then renamed: never half-written.
Status writePfm(const ImageRGB& image, const std::filesystem::path& file);
Result<ImageRGB> readPfm(const std::filesystem::path& file);
Status writePng8(const std::vector<unsigned char>& rgb8, int width, int height,
                 const std::filesystem::path& file);
// The same PNG as writePng8 writes, in memory (the HTML review sheet embeds its thumbnails).
// Empty when rgb8 does not hold width x height x 3 bytes.
std::string encodePng8(const std::vector<unsigned char>& rgb8, int width, int height);

}  // namespace haze
