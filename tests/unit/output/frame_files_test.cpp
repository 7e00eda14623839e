// Whether a frame file is complete (renderer/output/frame_files.h), the check behind --resume and
// `haze farm status`: whole PNGs and EXRs pass, the same files cut short anywhere do not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "renderer/output/exr.h"
#include "renderer/output/frame_files.h"
#include "shows/scene/image.h"

namespace haze {
namespace {

class FrameFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("haze_frame_files_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // A copy of `file` with only its first `bytes` bytes.
  std::filesystem::path cut(const std::filesystem::path& file, size_t bytes) {
    std::ifstream in(file, std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto out = dir_ / ("cut-" + std::to_string(bytes) + file.extension().string());
    std::ofstream(out, std::ios::binary) << all.substr(0, bytes);
    return out;
  }
  std::filesystem::path dir_;
};

TEST_F(FrameFiles, AWholePngIsCompleteAndReadsBack) {
  std::vector<unsigned char> rgb(32 * 8 * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<unsigned char>(i * 37);
  const auto png = dir_ / "f.png";
  ASSERT_TRUE(writePng8(rgb, 32, 8, png));
  EXPECT_TRUE(frameFileComplete(png));
  auto back = readPngRgb8(png);
  ASSERT_TRUE(back) << back.error().str();
  EXPECT_EQ(back->width, 32);
  EXPECT_EQ(back->height, 8);
  EXPECT_EQ(back->rgb, rgb);
  const size_t size = std::filesystem::file_size(png);
  // Cut in the pixel data, and cut only at the end (the IEND chunk missing).
  for (size_t bytes : {size_t{0}, size_t{40}, size / 2, size - 12, size - 1}) {
    EXPECT_FALSE(frameFileComplete(cut(png, bytes))) << bytes << " of " << size << " bytes";
  }
  EXPECT_FALSE(readPngRgb8(cut(png, size / 2)));
}

TEST_F(FrameFiles, AWholeExrIsCompleteACutOneIsNot) {
  ImageRGB image{.width = 16, .height = 16, .pixels = std::vector<glm::vec3>(256, glm::vec3(1.0f, 2.0f, 3.0f))};
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i].x = static_cast<float>(i);
  const auto exr = dir_ / "f.exr";
  ASSERT_TRUE(writeExr(image, exr));
  EXPECT_TRUE(frameFileComplete(exr));
  const size_t size = std::filesystem::file_size(exr);
  for (size_t bytes : {size_t{0}, size_t{100}, size / 2, size - 4}) {
    EXPECT_FALSE(frameFileComplete(cut(exr, bytes))) << bytes << " of " << size << " bytes";
  }
}

TEST_F(FrameFiles, MissingFilesAndOtherTypesAreNotFrames) {
  EXPECT_FALSE(frameFileComplete(dir_ / "absent.png"));
  std::ofstream(dir_ / "f.pfm") << "PF\n1 1\n-1\n";
  EXPECT_FALSE(frameFileComplete(dir_ / "f.pfm"));
  EXPECT_FALSE(frameFileComplete(dir_));
}

}  // namespace
}  // namespace haze
