// ArtTimeCode written field by field from the Art-Net 4 table, and timecode labels.
#include <gtest/gtest.h>

#include <vector>

#include "shows/dmx/artnet_timecode.h"

namespace haze {
namespace {

std::vector<uint8_t> artTimeCode(int h, int m, int s, int f, int type) {
  return {'A', 'r', 't', '-', 'N', 'e', 't', 0, 0x00, 0x97, 0, 14, 0, 0,
          static_cast<uint8_t>(f), static_cast<uint8_t>(s), static_cast<uint8_t>(m), static_cast<uint8_t>(h),
          static_cast<uint8_t>(type)};
}

TEST(ArtTimeCode, Fields) {
  const ArtTimeCodeParse p = parseArtTimeCode(artTimeCode(23, 59, 58, 24, 1));
  ASSERT_TRUE(p.ok());
  EXPECT_EQ(p.packet.time, (Timecode{23, 59, 58, 24}));
  EXPECT_DOUBLE_EQ(p.packet.fps(), 25.0);
  EXPECT_NEAR(parseArtTimeCode(artTimeCode(0, 0, 0, 0, 2)).packet.fps(), 29.97, 0.001);
}

TEST(ArtTimeCode, OutOfRangeIsRefused) {
  EXPECT_EQ(parseArtTimeCode(artTimeCode(24, 0, 0, 0, 1)).status, ArtTimeCodeStatus::BadTime) << "24 h and beyond";
  EXPECT_EQ(parseArtTimeCode(artTimeCode(0, 60, 0, 0, 1)).status, ArtTimeCodeStatus::BadTime);
  EXPECT_EQ(parseArtTimeCode(artTimeCode(0, 0, 60, 0, 1)).status, ArtTimeCodeStatus::BadTime);
  EXPECT_EQ(parseArtTimeCode(artTimeCode(0, 0, 0, 25, 1)).status, ArtTimeCodeStatus::BadTime) << "frame 25 at 25 fps";
  EXPECT_TRUE(parseArtTimeCode(artTimeCode(0, 0, 0, 29, 3)).ok());
  EXPECT_EQ(parseArtTimeCode(artTimeCode(0, 0, 0, 24, 0)).status, ArtTimeCodeStatus::BadTime);
  EXPECT_EQ(parseArtTimeCode(artTimeCode(0, 0, 0, 0, 4)).status, ArtTimeCodeStatus::BadType);
  auto cut = artTimeCode(0, 0, 0, 0, 1);
  cut.pop_back();
  EXPECT_EQ(parseArtTimeCode(cut).status, ArtTimeCodeStatus::TooShort);
  auto dmx = artTimeCode(0, 0, 0, 0, 1);
  dmx[9] = 0x50;  // OpDmx
  EXPECT_EQ(parseArtTimeCode(dmx).status, ArtTimeCodeStatus::NotTimeCode);
}

TEST(Timecode, LabelsParseAndOrder) {
  EXPECT_EQ(parseTimecode("01:02:03:04"), (Timecode{1, 2, 3, 4}));
  EXPECT_EQ(parseTimecode("01:02:03;04"), (Timecode{1, 2, 3, 4})) << "drop-frame spelling";
  EXPECT_EQ(parseTimecode("01:02:03:04")->str(), "01:02:03:04");
  for (const char* bad : {"24:00:00:00", "00:60:00:00", "00:00:60:00", "00:00:00:30", "1:02:03:04", "01:02:03",
                          "01-02-03-04", "", "aa:bb:cc:dd"})
    EXPECT_FALSE(parseTimecode(bad)) << bad;
  EXPECT_LT(*parseTimecode("00:00:59:29"), *parseTimecode("00:01:00:00"));
}

// Frame counts at an integer rate: 01:02:03:04 at 25 fps is (3600 + 120 + 3) * 25 + 4 frames.
TEST(Timecode, FrameCountsRoundTrip) {
  EXPECT_EQ(parseTimecode("01:02:03:04")->toFrames(25), 3723L * 25 + 4);
  EXPECT_EQ(Timecode::fromFrames(3723L * 25 + 4, 25), (Timecode{1, 2, 3, 4}));
  EXPECT_EQ(Timecode::fromFrames(86400L * 30 - 1, 30), (Timecode{23, 59, 59, 29}));
  EXPECT_FALSE(Timecode::fromFrames(86400L * 24, 24)) << "24:00:00:00 is beyond a day";
  EXPECT_FALSE(Timecode::fromFrames(-1, 25));
  for (long n : {0L, 1L, 23L, 24L, 1439L, 86399L * 24})
    EXPECT_EQ(Timecode::fromFrames(n, 24)->toFrames(24), n);
}

}  // namespace
}  // namespace haze
