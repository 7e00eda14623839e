// The EXR is made in memory (OpenEXR writes through an OStream) and then replaces the file
// atomically, like every file haze writes.
#include "renderer/output/exr.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <limits>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>

#include "fixtures/core/atomic_file.h"

namespace haze {
namespace {

class MemoryStream : public Imf::OStream {
 public:
  explicit MemoryStream(const std::string& name) : Imf::OStream(name.c_str()) {}
  void write(const char c[], int n) override {
    if (pos_ + n > bytes_.size()) bytes_.resize(pos_ + n);
    std::memcpy(bytes_.data() + pos_, c, static_cast<size_t>(n));
    pos_ += static_cast<size_t>(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = static_cast<size_t>(pos); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  size_t pos_ = 0;
};

}  // namespace

std::optional<ExrPixel> parseExrPixel(const std::string& name) {
  if (name == "half") return ExrPixel::Half;
  if (name == "float") return ExrPixel::Float;
  return std::nullopt;
}

Result<ExrWritten> writeExr(const ImageRGB& image, const std::filesystem::path& file, const ExrOptions& options) {
  if (image.width <= 0 || image.height <= 0 || image.pixels.size() != static_cast<size_t>(image.width) * image.height)
    return Error{file.string(), "", "internal: image buffer does not match its size"};
  ExrWritten written;
  const bool half = options.pixel == ExrPixel::Half;
  const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
  std::vector<Imath::half> halves;
  if (half) {
    // Beyond 65504 a half is infinity; a lamp's lens seen head-on can be brighter than that.
    constexpr float kHalfMax = 65504.0f;
    halves.resize(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
      bool clamped = false;
      for (int c = 0; c < 3; ++c) {
        float v = image.pixels[i][c];
        if (v > kHalfMax) {
          v = kHalfMax;
          clamped = true;
        }
        halves[i * 3 + c] = Imath::half(v);
      }
      if (clamped) ++written.clampedPixels;
    }
  }
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(type));
    Imf::addChromaticities(header, Imf::Chromaticities());  // Rec. 709 primaries, D65 white
    Imf::addWhiteLuminance(header, 1.0f);                   // the values are cd/m^2
    if (!options.comment.empty()) Imf::addComments(header, options.comment);

    Imf::FrameBuffer frameBuffer;
    const size_t pixelBytes = half ? 3 * sizeof(Imath::half) : sizeof(glm::vec3);
    const size_t channelBytes = half ? sizeof(Imath::half) : sizeof(float);
    char* base = half ? reinterpret_cast<char*>(halves.data())
                      : reinterpret_cast<char*>(const_cast<glm::vec3*>(image.pixels.data()));
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
      frameBuffer.insert(names[c], Imf::Slice(type, base + c * channelBytes, pixelBytes, pixelBytes * image.width));

    MemoryStream stream(file.string());
    {
      Imf::OutputFile out(stream, header);
      out.setFrameBuffer(frameBuffer);
      out.writePixels(image.height);
    }
    const Status s = writeFileAtomically(file, stream.bytes(), false);
    if (!s) return s.error();
  } catch (const std::exception& e) {
    return Error{file.string(), "", std::string("cannot write the EXR: ") + e.what()};
  }
  return written;
}

}  // namespace haze
