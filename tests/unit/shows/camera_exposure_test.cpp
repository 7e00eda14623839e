// A camera's "exposure" (docs/show-format.md): read, written back byte-stable, and refused when
// its mode is unknown or it has keys of its own.
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/show_json.h"

namespace haze {
namespace {

std::string withCameraExposure(const std::string& exposure) {
  auto a = loadShow(test::validShowPath());
  EXPECT_TRUE(a.ok());
  a->cameras = {CameraDef{.name = "FOH", .position = {0, 4, 18}}};
  std::string text = showToText(*a);
  const std::string key = "\"fov_y\": 40";
  const size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << text;
  if (!exposure.empty()) text.insert(at + key.size(), ", \"exposure\": " + exposure);
  return text;
}

TEST(CameraExposure, ReadsAndWritesBack) {
  ShowParse p = parseShowText(withCameraExposure(R"({"mode": "manual", "ev": -3.5})"), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  ASSERT_TRUE(p.show.cameras[0].exposure.has_value());
  EXPECT_TRUE(p.show.cameras[0].exposure->manual);
  EXPECT_FLOAT_EQ(p.show.cameras[0].exposure->ev, -3.5f);
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty());
  EXPECT_EQ(q.show.cameras[0].exposure, p.show.cameras[0].exposure);
  EXPECT_EQ(showToText(q.show), text);
}

TEST(CameraExposure, AbsentStaysAbsent) {
  ShowParse p = parseShowText(withCameraExposure(""), test::validShowPath());
  ASSERT_TRUE(p.problems.empty());
  EXPECT_FALSE(p.show.cameras[0].exposure.has_value());
  EXPECT_EQ(showToText(p.show).find("exposure"), std::string::npos);
}

TEST(CameraExposure, BadModeAndUnknownKeysAreProblems) {
  EXPECT_FALSE(parseShowText(withCameraExposure(R"({"mode": "program"})"), test::validShowPath()).problems.empty());
  EXPECT_FALSE(parseShowText(withCameraExposure(R"({"mode": "auto", "iso": 100})"), test::validShowPath()).problems.empty());
  EXPECT_FALSE(parseShowText(withCameraExposure(R"({"ev": 1})"), test::validShowPath()).problems.empty());
}

}  // namespace
}  // namespace haze
