// haze_output without the renderer: EXR's half clamping is counted (never silent), and the video
// writer's failures and interruptions leave nothing under the final name.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "renderer/output/exr.h"
#include "renderer/output/video_writer.h"

namespace haze {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("haze-output-test-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

bool onlyFileIn(const std::filesystem::path& dir, const std::filesystem::path& file) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path() != file) return false;
    ++n;
  }
  return n <= 1;
}

TEST(Exr, HalfCountsThePixelsItClamps) {
  ImageRGB image{.width = 4, .height = 2, .pixels = std::vector<glm::vec3>(8, glm::vec3(1.0f))};
  image.at(1, 0) = glm::vec3(70000.0f, 1.0f, 1.0f);  // above half's 65504
  image.at(3, 1) = glm::vec3(1.0f, 1e6f, 2e6f);       // two channels, one pixel
  image.at(2, 1) = glm::vec3(65504.0f);               // exactly the largest half: kept
  const auto file = scratch("clamp.exr");
  auto half = writeExr(image, file, {.pixel = ExrPixel::Half});
  ASSERT_TRUE(half) << half.error().str();
  EXPECT_EQ(half->clampedPixels, 2u);
  auto full = writeExr(image, file, {.pixel = ExrPixel::Float});
  ASSERT_TRUE(full);
  EXPECT_EQ(full->clampedPixels, 0u);
  EXPECT_TRUE(onlyFileIn(file.parent_path(), file)) << "a temporary file was left";
  std::filesystem::remove_all(file.parent_path());
}

TEST(Exr, AnUnwritableFolderIsAnErrorNamingTheFile) {
  ImageRGB image{.width = 1, .height = 1, .pixels = {glm::vec3(1.0f)}};
  auto r = writeExr(image, "/nonexistent-haze-folder/x.exr");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().str().find("/nonexistent-haze-folder/x.exr"), std::string::npos) << r.error().str();
}

TEST(VideoWriter, NamesAMissingEncoderAndAnOddSize) {
  const auto file = scratch("v.mp4");
  auto noCodec = VideoWriter::create(file, {.width = 32, .height = 18, .codec = "no-such-encoder"});
  ASSERT_FALSE(noCodec);
  EXPECT_NE(noCodec.error().str().find("no-such-encoder"), std::string::npos);
  auto odd = VideoWriter::create(file, {.width = 33, .height = 18});
  ASSERT_FALSE(odd);
  EXPECT_NE(odd.error().str().find("even"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(file));
  std::filesystem::remove_all(file.parent_path());
}

TEST(VideoWriter, UnfinishedLeavesNothingFinishedLeavesAnMp4) {
  const auto file = scratch("v.mp4");
  const std::vector<unsigned char> grey(32 * 18 * 3, 128);
  {
    auto w = VideoWriter::create(file, {.width = 32, .height = 18, .fps = 10});
    ASSERT_TRUE(w) << w.error().str();
    ASSERT_TRUE((*w)->addFrame(grey));
  }  // dropped without finish(): an interrupted encode
  EXPECT_TRUE(std::filesystem::is_empty(file.parent_path()));
  auto w = VideoWriter::create(file, {.width = 32, .height = 18, .fps = 10});
  ASSERT_TRUE(w);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE((*w)->addFrame(grey));
  EXPECT_FALSE(std::filesystem::exists(file)) << "the final name appears only when finished";
  ASSERT_TRUE((*w)->finish());
  EXPECT_EQ((*w)->frames(), 5);
  std::ifstream in(file, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  EXPECT_EQ(std::string(head + 4, 4), "ftyp");  // an ISO base media file (MP4) box
  EXPECT_TRUE(onlyFileIn(file.parent_path(), file));
  std::filesystem::remove_all(file.parent_path());
}

}  // namespace
}  // namespace haze
