#include "renderer/output/frame_files.h"

#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>

#include <Imath/ImathBox.h>
#include <OpenEXR/ImfArray.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <stb/stb_image.h>

namespace haze {
namespace {

std::string readBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Every PNG ends with an empty IEND chunk: length 0, "IEND", its fixed CRC.
bool endsWithIend(const std::string& bytes) {
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  return bytes.size() >= 12 && std::memcmp(bytes.data() + bytes.size() - 12, iend, 12) == 0;
}

bool exrComplete(const std::filesystem::path& file) {
  try {
    Imf::RgbaInputFile in(file.string().c_str());
    if (!in.isComplete()) return false;
    const Imath::Box2i window = in.dataWindow();
    const long width = window.max.x - window.min.x + 1;
    const long height = window.max.y - window.min.y + 1;
    Imf::Array2D<Imf::Rgba> pixels(height, width);
    // A damaged or missing scan line throws.
    in.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * width, 1, static_cast<size_t>(width));
    in.readPixels(window.min.y, window.max.y);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

bool frameFileComplete(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return false;
  if (file.extension() == ".exr") return exrComplete(file);
  if (file.extension() != ".png") return false;
  return static_cast<bool>(readPngRgb8(file));
}

Result<Rgb8Image> readPngRgb8(const std::filesystem::path& file) {
  const std::string bytes = readBytes(file);
  if (bytes.empty()) return Error{file.string(), "", "cannot read the frame (missing or empty)"};
  if (!endsWithIend(bytes)) return Error{file.string(), "", "the PNG is cut short (no IEND chunk at its end)"};
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<int>(bytes.size()), &w, &h, &channels, 3);
  if (!data) return Error{file.string(), "", std::string("the PNG does not decode: ") + stbi_failure_reason()};
  Rgb8Image image{.width = w, .height = h, .rgb = std::vector<unsigned char>(data, data + static_cast<size_t>(w) * h * 3)};
  stbi_image_free(data);
  return image;
}

}  // namespace haze
