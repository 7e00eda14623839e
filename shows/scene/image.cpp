// PFM (radiometric float output, what tests compare) and PNG (display) files. Both are written
// to a temporary name in the target's folder and renamed, so a reader never sees half a file.
#include "shows/scene/image.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <stb_image_write.h>

namespace haze {
namespace {

std::filesystem::path tempBeside(const std::filesystem::path& file) {
  return file.parent_path() / ("." + file.filename().string() + ".tmp");
}

Status commit(const std::filesystem::path& tmp, const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    return Error{file.string(), "", "cannot write the image: " + ec.message()};
  }
  return Ok{};
}

}  // namespace

Status writePfm(const ImageRGB& image, const std::filesystem::path& file) {
  const auto tmp = tempBeside(file);
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) return Error{file.string(), "", "cannot create the file (does the folder exist?)"};
    out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";  // negative: little-endian
    // PFM stores the bottom row first.
    for (int y = image.height - 1; y >= 0; --y)
      out.write(reinterpret_cast<const char*>(&image.pixels[static_cast<size_t>(y) * image.width]),
                static_cast<std::streamsize>(sizeof(glm::vec3) * image.width));
    if (!out) return Error{file.string(), "", "write failed (disk full?)"};
  }
  return commit(tmp, file);
}

Result<ImageRGB> readPfm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{file.string(), "", "cannot open the file"};
  std::string magic;
  int w = 0, h = 0;
  double scale = 0.0;
  in >> magic >> w >> h >> scale;
  in.get();
  if (magic != "PF" || w <= 0 || h <= 0 || w > 65536 || h > 65536 || scale >= 0.0)
    return Error{file.string(), "header", "expected a little-endian colour PFM (PF, width, height, negative scale)"};
  ImageRGB img;
  img.width = w;
  img.height = h;
  img.pixels.resize(static_cast<size_t>(w) * h);
  for (int y = h - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(&img.pixels[static_cast<size_t>(y) * w]),
            static_cast<std::streamsize>(sizeof(glm::vec3) * w));
  if (!in) return Error{file.string(), "data", "the file ends before its " + std::to_string(h) + " rows"};
  return img;
}

Status writePng8(const std::vector<unsigned char>& rgb8, int width, int height,
                 const std::filesystem::path& file) {
  if (rgb8.size() != static_cast<size_t>(width) * height * 3)
    return Error{file.string(), "", "internal: image buffer does not match its size"};
  const auto tmp = tempBeside(file);
  if (!stbi_write_png(tmp.string().c_str(), width, height, 3, rgb8.data(), width * 3))
    return Error{file.string(), "", "cannot write the PNG (does the folder exist?)"};
  return commit(tmp, file);
}

std::string encodePng8(const std::vector<unsigned char>& rgb8, int width, int height) {
  if (width <= 0 || height <= 0 || rgb8.size() != static_cast<size_t>(width) * height * 3) return {};
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &bytes, width, height, 3, rgb8.data(), width * 3)) return {};
  return bytes;
}

}  // namespace haze
