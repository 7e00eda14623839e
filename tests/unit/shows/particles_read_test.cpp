// atmosphere.particles (docs/shows.md, "Particles"): read, written back byte-stable, and bad
// values refused with their JSON pointers.
#include <gtest/gtest.h>

#include "show_test_data.h"
#include "shows/show_json.h"

namespace haze {
namespace {

std::string withParticles(const std::string& particles) {
  auto a = loadShow(test::validShowPath());
  EXPECT_TRUE(a.ok());
  std::string text = showToText(*a);
  const std::string key = "\"atmosphere\": {";
  const size_t at = text.find(key);
  EXPECT_NE(at, std::string::npos) << text;
  text.insert(at + key.size(), "\"particles\": " + particles + ", ");
  return text;
}

TEST(ParticlesRead, ReadsEveryKeyAndWritesItBack) {
  ShowParse p = parseShowText(
      withParticles(R"({"enabled": true, "density": 20, "size_um": 60, "size_sigma": 0.3, "brightness": 500, "seed": 7})"),
      test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  ASSERT_TRUE(p.show.atmosphere.particles.has_value());
  const ParticleSettings& ps = *p.show.atmosphere.particles;
  EXPECT_TRUE(ps.enabled);
  EXPECT_FLOAT_EQ(ps.densityPerM3, 20.0f);
  EXPECT_FLOAT_EQ(ps.sizeUm, 60.0f);
  EXPECT_FLOAT_EQ(ps.sizeSigma, 0.3f);
  EXPECT_FLOAT_EQ(ps.brightness, 500.0f);
  EXPECT_EQ(ps.seed, 7u);
  const std::string text = showToText(p.show);
  ShowParse q = parseShowText(text, test::validShowPath());
  ASSERT_TRUE(q.problems.empty()) << q.problems[0].str();
  EXPECT_EQ(*q.show.atmosphere.particles, ps);
  EXPECT_EQ(showToText(q.show), text);
}

TEST(ParticlesRead, DefaultsAndAbsence) {
  ShowParse p = parseShowText(withParticles(R"({"enabled": false})"), test::validShowPath());
  ASSERT_TRUE(p.problems.empty()) << p.problems[0].str();
  ASSERT_TRUE(p.show.atmosphere.particles.has_value());
  EXPECT_EQ(*p.show.atmosphere.particles, ParticleSettings{});
  auto a = loadShow(test::validShowPath());
  ASSERT_TRUE(a.ok());
  EXPECT_FALSE(a->atmosphere.particles.has_value());
  EXPECT_EQ(showToText(*a).find("particles"), std::string::npos);
}

std::string problemsOf(const std::string& particles) {
  std::string all;
  for (const Error& e : parseShowText(withParticles(particles), test::validShowPath()).problems) all += e.str() + "\n";
  return all;
}

TEST(ParticlesRead, BadValuesNameTheirPlace) {
  EXPECT_NE(problemsOf(R"({"density": -1})").find("/atmosphere/particles/density"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"density": 1e6})").find("/atmosphere/particles/density"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"enabled": "yes"})").find("/atmosphere/particles/enabled"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"size_um": 0})").find("/atmosphere/particles/size_um"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"seed": 1.5})").find("/atmosphere/particles/seed"), std::string::npos);
  EXPECT_NE(problemsOf(R"({"dust": 1})").find("/atmosphere/particles/dust"), std::string::npos);
  EXPECT_NE(problemsOf(R"(3)").find("/atmosphere/particles"), std::string::npos);
}

}  // namespace
}  // namespace haze
