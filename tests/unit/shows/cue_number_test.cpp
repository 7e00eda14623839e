// Cue numbers are decimal strings compared as numbers: "1" < "1.5" < "10".
#include <gtest/gtest.h>

#include "shows/cue_number.h"

namespace haze {

TEST(CueNumber, RecognisesDecimalStrings) {
  for (const char* ok : {"1", "0", "10", "1.5", "0.25", "007", "1.50"}) EXPECT_TRUE(isCueNumber(ok)) << ok;
  for (const char* bad : {"", ".", "1.", ".5", "1.2.3", "-1", "1e3", "A", " 1", "1,5"})
    EXPECT_FALSE(isCueNumber(bad)) << bad;
}

TEST(CueNumber, ComparesNumericallyNotAsText) {
  EXPECT_LT(compareCueNumbers("1", "1.5"), 0);
  EXPECT_LT(compareCueNumbers("1.5", "10"), 0);
  EXPECT_LT(compareCueNumbers("9", "10"), 0);     // as text "9" > "10"
  EXPECT_LT(compareCueNumbers("1.5", "1.55"), 0);
  EXPECT_LT(compareCueNumbers("1.55", "1.6"), 0);  // as lengths 1.55 would win
  EXPECT_GT(compareCueNumbers("2", "1.999"), 0);
  EXPECT_GT(compareCueNumbers("100", "99.9"), 0);
}

TEST(CueNumber, EqualSpellingsAreTheSameCue) {
  EXPECT_EQ(compareCueNumbers("1.5", "1.50"), 0);
  EXPECT_EQ(compareCueNumbers("1", "1.0"), 0);
  EXPECT_EQ(compareCueNumbers("01", "1"), 0);
  EXPECT_EQ(compareCueNumbers("0", "00.000"), 0);
}

}  // namespace haze
