// MIDI Time Code from the bytes of the MMA MTC specification, written out here by hand: eight
// quarter-frame messages F1 0n (piece n >> 4, nibble n & 15) spell a time that the decoder
// reports two frames later (they took two frames to send); Full Frame sysex
// F0 7F 7F 01 01 hr mn sc fr F7 gives a time at once; drop-frame numbering skips frames 0 and 1
// at each minute but every tenth.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "shows/dmx/midi_timecode.h"

namespace haze {
namespace {

using Bytes = std::vector<uint8_t>;

// 01:02:03:04 at 25 fps (rate code 1): pieces 0..7 = frames 4|0, seconds 3|0, minutes 2|0,
// hours 1, and hours-high 0 with the rate in bits 1-2 (1 << 1 = 2).
const Bytes kForward = {0xF1, 0x04, 0xF1, 0x10, 0xF1, 0x23, 0xF1, 0x30,
                        0xF1, 0x42, 0xF1, 0x50, 0xF1, 0x61, 0xF1, 0x72};

TEST(MidiTimecode, QuarterFramesForwardReadTwoFramesOn) {
  MtcDecoder d;
  const auto r = d.feed(kForward);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].time, (Timecode{1, 2, 3, 6}));
  EXPECT_EQ(r[0].rateCode, 1);
  EXPECT_DOUBLE_EQ(r[0].fps(), 25.0);
  EXPECT_FALSE(r[0].fullFrame);
  EXPECT_EQ(d.stats().quarterFrames, 8u);
}

TEST(MidiTimecode, HighNibblesAndThirtyFps) {
  // 23:59:59:27 at 30 fps: frames 27 = 0x1B, seconds and minutes 59 = 0x3B, hours 23 = 0x17;
  // piece 7 = hours bit 4 (1) | rate 3 << 1 = 7.
  MtcDecoder d;
  const auto r = d.feed(Bytes{0xF1, 0x0B, 0xF1, 0x11, 0xF1, 0x2B, 0xF1, 0x33,
                              0xF1, 0x4B, 0xF1, 0x53, 0xF1, 0x67, 0xF1, 0x77});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].time, (Timecode{23, 59, 59, 29}));
  EXPECT_EQ(r[0].rateCode, 3);
  // Two frames after 23:59:59:28 is past midnight: no reading rather than a wrong one.
  EXPECT_TRUE(d.feed(Bytes{0xF1, 0x0C, 0xF1, 0x11, 0xF1, 0x2B, 0xF1, 0x33,
                           0xF1, 0x4B, 0xF1, 0x53, 0xF1, 0x67, 0xF1, 0x77}).empty());
}

TEST(MidiTimecode, BackwardsReadsTwoFramesBack) {
  MtcDecoder d;
  Bytes backward;
  for (size_t i = kForward.size(); i >= 2; i -= 2) backward.insert(backward.end(), {kForward[i - 2], kForward[i - 1]});
  const auto r = d.feed(backward);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].time, (Timecode{1, 2, 3, 2}));
}

TEST(MidiTimecode, FullFrameAndSplitInput) {
  MtcDecoder d;
  // hr = 25 fps (1) << 5 | 1 hour = 0x21; a timing clock byte (F8) inside is ignored, and the
  // message arrives in three pieces.
  const Bytes full = {0xF0, 0x7F, 0x7F, 0x01, 0xF8, 0x01, 0x21, 0x02, 0x03, 0x04, 0xF7};
  EXPECT_TRUE(d.feed(std::span(full).first(3)).empty());
  EXPECT_TRUE(d.feed(std::span(full).subspan(3, 5)).empty());
  const auto r = d.feed(std::span(full).subspan(8));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].time, (Timecode{1, 2, 3, 4}));
  EXPECT_TRUE(r[0].fullFrame);
  EXPECT_EQ(d.stats().fullFrames, 1u);
  // Other sysex (a device inquiry) and channel messages are skipped.
  EXPECT_TRUE(d.feed(Bytes{0xF0, 0x7E, 0x7F, 0x06, 0x01, 0xF7, 0x90, 0x40, 0x7F, 0xB0, 0x07, 0x64}).empty());
  // Quarter frames split byte by byte still assemble.
  std::vector<MtcReading> all;
  for (uint8_t b : kForward)
    for (const auto& x : d.feed(Bytes{b})) all.push_back(x);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].time, (Timecode{1, 2, 3, 6}));
}

TEST(MidiTimecode, BrokenCyclesAndBadTimesAreCounted) {
  MtcDecoder d;
  // Piece 2 missing: that cycle gives nothing; the next whole one does.
  Bytes broken = {0xF1, 0x04, 0xF1, 0x10, 0xF1, 0x30, 0xF1, 0x42, 0xF1, 0x50, 0xF1, 0x61, 0xF1, 0x72};
  EXPECT_TRUE(d.feed(broken).empty());
  EXPECT_EQ(d.stats().brokenCycles, 1u);
  EXPECT_EQ(d.feed(kForward).size(), 1u);
  // Minutes 60 in a full frame; frames 25 at 25 fps in quarter frames (25 = 0x19).
  EXPECT_TRUE(d.feed(Bytes{0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x21, 0x3C, 0x03, 0x04, 0xF7}).empty());
  EXPECT_TRUE(d.feed(Bytes{0xF1, 0x09, 0xF1, 0x11, 0xF1, 0x23, 0xF1, 0x30,
                           0xF1, 0x42, 0xF1, 0x50, 0xF1, 0x61, 0xF1, 0x72}).empty());
  EXPECT_EQ(d.stats().badTimes, 2u);
  // A full frame mid-cycle restarts the assembly: the pieces before it are not mixed in.
  Bytes mixed(kForward.begin(), kForward.begin() + 8);
  mixed.insert(mixed.end(), {0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x21, 0x02, 0x03, 0x04, 0xF7});
  mixed.insert(mixed.end(), kForward.begin() + 8, kForward.end());
  const auto r = d.feed(mixed);
  ASSERT_EQ(r.size(), 1u) << "only the full frame";
  EXPECT_TRUE(r[0].fullFrame);
}

TEST(MidiTimecode, DropFrameSkipsFramesZeroAndOne) {
  EXPECT_EQ(stepFrame(Timecode{0, 0, 59, 29}, 2, 1), (Timecode{0, 1, 0, 2}));
  EXPECT_EQ(stepFrame(Timecode{0, 9, 59, 29}, 2, 1), (Timecode{0, 10, 0, 0})) << "every tenth minute keeps them";
  EXPECT_EQ(stepFrame(Timecode{0, 1, 0, 2}, 2, -1), (Timecode{0, 0, 59, 29}));
  EXPECT_EQ(stepFrame(Timecode{0, 0, 59, 29}, 3, 1), (Timecode{0, 1, 0, 0})) << "30 fps drops nothing";
  EXPECT_FALSE(stepFrame(Timecode{0, 0, 0, 0}, 1, -1));
  // Drop-frame quarter frames: 00:00:59:28 (rate code 2: piece 7 = 4) reads 00:01:00:02.
  MtcDecoder d;
  const auto r = d.feed(Bytes{0xF1, 0x0C, 0xF1, 0x11, 0xF1, 0x2B, 0xF1, 0x33,
                              0xF1, 0x40, 0xF1, 0x50, 0xF1, 0x60, 0xF1, 0x74});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].time, (Timecode{0, 1, 0, 2}));
  EXPECT_NEAR(r[0].fps(), 29.97, 0.001);
}

// Random bytes (mostly quarter frames, some sysex starts) never give a time out of range.
TEST(MidiTimecode, RandomBytesGiveOnlyValidTimes) {
  std::mt19937 rng(16);
  MtcDecoder d;
  for (int round = 0; round < 2000; ++round) {
    Bytes b;
    for (int i = 0; i < 64; ++i) {
      const int kind = static_cast<int>(rng() % 8);
      b.push_back(kind < 5 ? 0xF1 : kind == 5 ? 0xF0 : static_cast<uint8_t>(rng()));
      b.push_back(static_cast<uint8_t>(rng() & (kind < 6 ? 0x7F : 0xFF)));
    }
    for (const MtcReading& r : d.feed(b)) {
      EXPECT_LE(r.time.hours, 23);
      EXPECT_LE(r.time.minutes, 59);
      EXPECT_LE(r.time.seconds, 59);
      EXPECT_LT(r.time.frames, r.rateCode == 0 ? 24 : r.rateCode == 1 ? 25 : 30);
    }
  }
  EXPECT_GT(d.stats().quarterFrames, 0u);
}

}  // namespace
}  // namespace haze
