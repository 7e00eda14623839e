// atmosphere.density (docs/shows.md, "Density"): read, written back byte-stable, and bad values
// refused with their JSON pointers.
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/show_json.h"

namespace haze {
namespace {

std::string withDensity(const std::string& density) {
  auto a = loadShow(test::validShowPath());
  EXPECT_TRUE(a.ok());
  std::string text = showToText(*a);
  const std::string key = "\"atmosphere\": {";
  const size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << text;
  text.insert(at + key.size(), "\"density\": " + density + ", ");
  return text;
}

const char* kFull = R"({"base": 0.3, "grid": [32, 16, 24], "bounds": [[-5, 0, -5], [5, 6, 5]],
  "air_flow": [0.1, 0, -0.2], "mixing": 0.08, "dissipation": 0.01, "warmup": 30, "still": true,
  "fog": {"density": 4, "height": 0.4, "falloff": 0.25},
  "boxes": [{"min": [-1, 0, -1], "max": [1, 2, 1], "density": 2.5}],
  "hazers": [{"position": [4, 0.3, -4], "direction": [-1, 0.2, 0.5], "output": 1.5, "spread": 40, "speed": 3}]})";

TEST(DensityRead, ReadsEveryKeyAndWritesItBack) {
  ShowParse p = parseShowText(withDensity(kFull), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  ASSERT_TRUE(p.show.atmosphere.density.has_value());
  const DensitySpec& d = *p.show.atmosphere.density;
  EXPECT_FLOAT_EQ(d.base, 0.3f);
  EXPECT_EQ(d.grid[0], 32);
  EXPECT_EQ(d.grid[2], 24);
  ASSERT_TRUE(d.boundsMaxM.has_value());
  EXPECT_EQ(*d.boundsMaxM, glm::vec3(5, 6, 5));
  EXPECT_EQ(d.airFlowMps, glm::vec3(0.1f, 0, -0.2f));
  EXPECT_TRUE(d.still);
  EXPECT_DOUBLE_EQ(d.warmupS, 30.0);
  ASSERT_TRUE(d.fog.has_value());
  EXPECT_FLOAT_EQ(d.fog->falloffM, 0.25f);
  ASSERT_EQ(d.boxes.size(), 1u);
  EXPECT_FLOAT_EQ(d.boxes[0].density, 2.5f);
  ASSERT_EQ(d.hazers.size(), 1u);
  EXPECT_FLOAT_EQ(d.hazers[0].output, 1.5f);
  EXPECT_FLOAT_EQ(d.hazers[0].spreadDeg, 40.0f);
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(*q.show.atmosphere.density, d);
  EXPECT_EQ(showToText(q.show), text);
}

TEST(DensityRead, AbsentStaysAbsent) {
  auto a = loadShow(test::validShowPath());
  ASSERT_TRUE(a.ok());
  EXPECT_FALSE(a->atmosphere.density.has_value());
  EXPECT_EQ(showToText(*a).find("density"), std::string::npos);
}

std::string problemsOf(const std::string& density) {
  std::string all;
  for (const Error& e : parseShowText(withDensity(density), test::validShowPath()).problems) all += e.str() + "\n";
  return all;
}

TEST(DensityRead, BadValuesNameTheirPlace) {
  const std::string big = problemsOf(R"({"grid": [512, 512, 512]})");
  EXPECT_NE(big.find("/atmosphere/density/grid"), std::string::npos) << big;
  EXPECT_NE(big.find("needs about"), std::string::npos) << big;
  EXPECT_NE(problemsOf(R"({"grid": 300})").find("/atmosphere/density/grid"), std::string::npos);
  const std::string negative = problemsOf(R"({"hazers": [{"position": [0, 1, 0], "output": -1}]})");
  EXPECT_NE(negative.find("/atmosphere/density/hazers/0/output"), std::string::npos) << negative;
  EXPECT_NE(negative.find("from 0 to"), std::string::npos) << negative;
  EXPECT_NE(problemsOf(R"({"hazers": [{"direction": [0, 1, 0]}]})").find("/atmosphere/density/hazers/0/position"),
            std::string::npos);
  EXPECT_NE(problemsOf(R"({"fog": {"density": 1, "falloff": 0}})").find("/atmosphere/density/fog/falloff"),
            std::string::npos);
  EXPECT_NE(problemsOf(R"({"bounds": [[0, 0, 0], [1, -1, 1]]})").find("/atmosphere/density/bounds"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"smoke": 1})").find("/atmosphere/density/smoke"), std::string::npos);
}

}  // namespace
}  // namespace haze
