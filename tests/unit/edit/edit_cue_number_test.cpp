// Cue numbers chosen between neighbours, checked against hand-worked decimal answers.
#include <gtest/gtest.h>

#include "shows/cue_number.h"
#include "shows/edit/edit_cue_number.h"

namespace haze {
namespace {

std::string between(std::optional<std::string_view> a, std::optional<std::string_view> b) {
  Result<std::string> r = cueNumberBetween(a, b);
  return r ? *r : "error: " + r.error().message;
}

TEST(EditCueNumber, MiddleOfTheShortestDecimalsBetween) {
  EXPECT_EQ(between("1", "2"), "1.5");
  EXPECT_EQ(between("1", "3"), "2");
  EXPECT_EQ(between("1", "10"), "5");
  EXPECT_EQ(between("1", "1.5"), "1.2");
  EXPECT_EQ(between("1.5", "2"), "1.7");
  EXPECT_EQ(between("1.1", "1.2"), "1.15");
  EXPECT_EQ(between("1.19", "1.2"), "1.195");
  EXPECT_EQ(between("1.25", "1.3"), "1.27");
  EXPECT_EQ(between("9", "10"), "9.5");
  EXPECT_EQ(between("1.50", "2.0"), "1.7");
  EXPECT_EQ(between("99999999999999999998", "99999999999999999999"), "99999999999999999998.5");
}

TEST(EditCueNumber, EndsAndErrors) {
  EXPECT_EQ(between("3", std::nullopt), "4");
  EXPECT_EQ(between("3.5", std::nullopt), "4");
  EXPECT_EQ(between("9.99", std::nullopt), "10");
  EXPECT_EQ(between(std::nullopt, std::nullopt), "1");
  EXPECT_EQ(between(std::nullopt, "1"), "0.5");
  EXPECT_EQ(between(std::nullopt, "0.1"), "0.05");
  EXPECT_NE(between(std::nullopt, "0").find("error"), std::string::npos);
  EXPECT_NE(between("2", "1").find("error"), std::string::npos);
  EXPECT_NE(between("2", "2.00").find("error"), std::string::npos);
  EXPECT_NE(between("2x", "3").find("not a cue number"), std::string::npos);
}

TEST(EditCueNumber, AlwaysStrictlyBetweenForManyPairs) {
  const char* numbers[] = {"0", "0.01", "0.5", "1", "1.05", "1.1", "1.15", "1.2", "2", "2.999", "3", "10", "10.5", "100"};
  for (const char* a : numbers)
    for (const char* b : numbers) {
      if (compareCueNumbers(a, b) >= 0) continue;
      Result<std::string> n = cueNumberBetween(a, b);
      ASSERT_TRUE(n.ok()) << a << " " << b;
      EXPECT_TRUE(isCueNumber(*n)) << *n;
      EXPECT_LT(compareCueNumbers(a, *n), 0) << a << " " << *n;
      EXPECT_LT(compareCueNumbers(*n, b), 0) << *n << " " << b;
    }
}

}  // namespace
}  // namespace haze
