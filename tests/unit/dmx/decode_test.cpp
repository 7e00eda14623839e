// DMX footprint -> Attributes: 16-bit pan/tilt to degrees, CMY and RGB(W) to one colour filter,
// wheel slot ranges, short footprints. Expected values are worked out by hand in the comments.
#include <gtest/gtest.h>

#include "fixtures/dmx_decode.h"
#include "unit/dmx/test_show.h"

namespace haze {
namespace {

// Spot "Standard": Dimmer, Pan, Pan fine, Tilt, Tilt fine, C, M, Y, Gobo, Zoom, Strobe.
std::vector<uint8_t> spotLevels(uint8_t dimmer, uint16_t pan, uint16_t tilt, uint8_t c, uint8_t m,
                                uint8_t y, uint8_t gobo, uint8_t zoom) {
  return {dimmer, static_cast<uint8_t>(pan >> 8), static_cast<uint8_t>(pan & 0xFF),
          static_cast<uint8_t>(tilt >> 8), static_cast<uint8_t>(tilt & 0xFF), c, m, y, gobo, zoom, 0};
}

TEST(Decode, SixteenBitPanAndTiltToDegrees) {
  const auto p = test::spotProfile();
  const DmxMode& mode = p->modes[0];
  // Pan -270..270 over 0..65535: 0xFFFF is +270, 0 is -270; 0x4000 = 16384 is
  // -270 + 540 * 16384 / 65535 = -134.99794.
  EXPECT_FLOAT_EQ(decodeDmx(*p, mode, spotLevels(0, 0xFFFF, 0, 0, 0, 0, 0, 0)).panDeg, 270.0f);
  EXPECT_FLOAT_EQ(decodeDmx(*p, mode, spotLevels(0, 0x0000, 0, 0, 0, 0, 0, 0)).panDeg, -270.0f);
  EXPECT_NEAR(decodeDmx(*p, mode, spotLevels(0, 0x4000, 0, 0, 0, 0, 0, 0)).panDeg, -134.99794f, 1e-4);
  // The fine byte moves pan by 540 / 65535 = 0.0082399 degrees per step.
  const float a = decodeDmx(*p, mode, spotLevels(0, 0x8000, 0, 0, 0, 0, 0, 0)).panDeg;
  const float b = decodeDmx(*p, mode, spotLevels(0, 0x8001, 0, 0, 0, 0, 0, 0)).panDeg;
  EXPECT_NEAR(b - a, 0.0082399f, 1e-5);
  EXPECT_NEAR(a, 0.0041199f, 1e-4);  // 0x8000 is just past the middle
  // Tilt -135..135: 0xC000 = 49152 -> -135 + 270 * 49152 / 65535 = 67.50309.
  EXPECT_NEAR(decodeDmx(*p, mode, spotLevels(0, 0, 0xC000, 0, 0, 0, 0, 0)).tiltDeg, 67.50309f, 1e-4);
}

TEST(Decode, DimmerAndZoom) {
  const auto p = test::spotProfile();
  const Attributes a = decodeDmx(*p, p->modes[0], spotLevels(51, 0, 0, 0, 0, 0, 0, 255));
  EXPECT_FLOAT_EQ(a.intensity, 0.2f);  // 51 / 255
  ASSERT_TRUE(a.zoomDeg.has_value());
  EXPECT_FLOAT_EQ(*a.zoomDeg, 40.0f);
  EXPECT_FLOAT_EQ(*decodeDmx(*p, p->modes[0], spotLevels(0, 0, 0, 0, 0, 0, 0, 0)).zoomDeg, 8.0f);
}

TEST(Decode, CmyToColour) {
  const auto p = test::spotProfile();
  const DmxMode& mode = p->modes[0];
  // Full cyan removes red: (0, 1, 1).
  Attributes a = decodeDmx(*p, mode, spotLevels(255, 0, 0, 255, 0, 0, 0, 0));
  EXPECT_FLOAT_EQ(a.color.r, 0.0f);
  EXPECT_FLOAT_EQ(a.color.g, 1.0f);
  EXPECT_FLOAT_EQ(a.color.b, 1.0f);
  // Magenta 102 and yellow 255: (1, 1 - 0.4, 0).
  a = decodeDmx(*p, mode, spotLevels(255, 0, 0, 0, 102, 255, 0, 0));
  EXPECT_FLOAT_EQ(a.color.r, 1.0f);
  EXPECT_FLOAT_EQ(a.color.g, 0.6f);
  EXPECT_FLOAT_EQ(a.color.b, 0.0f);
  // No colour: white, and the dimmer stays the intensity.
  a = decodeDmx(*p, mode, spotLevels(255, 0, 0, 0, 0, 0, 0, 0));
  EXPECT_EQ(a.color, glm::vec3(1.0f));
  EXPECT_FLOAT_EQ(a.intensity, 1.0f);
}

TEST(Decode, GoboSlotRanges) {
  const auto p = test::spotProfile();
  const DmxMode& mode = p->modes[0];
  const std::pair<uint8_t, const char*> cases[] = {
      {0, "Open"}, {9, "Open"}, {10, "Dots"}, {19, "Dots"}, {20, "Stars"},
      {29, "Stars"}, {30, "Breakup"}, {255, "Breakup"}};
  for (const auto& [value, name] : cases) {
    EXPECT_EQ(decodeDmx(*p, mode, spotLevels(0, 0, 0, 0, 0, 0, value, 0)).gobo, name) << int(value);
  }
}

TEST(Decode, WheelWithoutRangesSplitsEvenly) {
  auto p = test::spotProfile();
  p->modes[0].channels[8].slotRanges.clear();
  const DmxMode& mode = p->modes[0];
  // Four slots over 0..255: 0-63, 64-127, 128-191, 192-255.
  EXPECT_EQ(decodeDmx(*p, mode, spotLevels(0, 0, 0, 0, 0, 0, 63, 0)).gobo, "Open");
  EXPECT_EQ(decodeDmx(*p, mode, spotLevels(0, 0, 0, 0, 0, 0, 64, 0)).gobo, "Dots");
  EXPECT_EQ(decodeDmx(*p, mode, spotLevels(0, 0, 0, 0, 0, 0, 191, 0)).gobo, "Stars");
  EXPECT_EQ(decodeDmx(*p, mode, spotLevels(0, 0, 0, 0, 0, 0, 192, 0)).gobo, "Breakup");
}

TEST(Decode, ValueInNoRangeKeepsOpen) {
  auto p = test::spotProfile();
  p->modes[0].channels[8].slotRanges = {{100, 110, 2}};
  EXPECT_EQ(decodeDmx(*p, p->modes[0], spotLevels(0, 0, 0, 0, 0, 0, 50, 0)).gobo, "Open");
  EXPECT_EQ(decodeDmx(*p, p->modes[0], spotLevels(0, 0, 0, 0, 0, 0, 105, 0)).gobo, "Stars");
}

TEST(Decode, RgbWithoutDimmerSplitsIntoIntensityAndColour) {
  const auto p = test::parProfile();
  const DmxMode& rgb = p->modes[0];
  // (128, 64, 0): the brightest component 128/255 is the intensity, the colour (1, 0.5, 0).
  std::vector<uint8_t> levels = {128, 64, 0};
  Attributes a = decodeDmx(*p, rgb, levels);
  EXPECT_FLOAT_EQ(a.intensity, 128.0f / 255.0f);
  EXPECT_FLOAT_EQ(a.color.r, 1.0f);
  EXPECT_FLOAT_EQ(a.color.g, 0.5f);
  EXPECT_FLOAT_EQ(a.color.b, 0.0f);
  levels = {0, 0, 0};
  a = decodeDmx(*p, rgb, levels);
  EXPECT_FLOAT_EQ(a.intensity, 0.0f);
}

TEST(Decode, WhiteAddsToEveryComponent) {
  const auto p = test::parProfile();
  // Dimmer 255, R 255, G 0, B 0, W 51: colour (1, 0.2, 0.2).
  const std::vector<uint8_t> levels = {255, 255, 0, 0, 51};
  const Attributes a = decodeDmx(*p, p->modes[1], levels);
  EXPECT_FLOAT_EQ(a.intensity, 1.0f);
  EXPECT_FLOAT_EQ(a.color.r, 1.0f);
  EXPECT_FLOAT_EQ(a.color.g, 0.2f);
  EXPECT_FLOAT_EQ(a.color.b, 0.2f);
}

TEST(Decode, ColourWheelFiltersTheMix) {
  auto p = test::spotProfile();
  p->colorWheels.push_back({"Colour", {{"White", glm::vec3(1.0f), "", nullptr},
                                        {"Red", glm::vec3(1.0f, 0.0f, 0.0f), "", nullptr},
                                        {"Congo", glm::vec3(0.2f, 0.0f, 0.8f), "", nullptr}}});
  DmxChannel wheel = test::channel("Color wheel", DmxAttribute::ColorWheel);
  wheel.slotRanges = {{0, 9, 0}, {10, 19, 1}, {20, 29, 2}};
  p->modes[0].channels[10] = wheel;  // replaces Strobe
  const DmxMode& mode = p->modes[0];
  auto levels = spotLevels(255, 0, 0, 0, 0, 0, 0, 0);
  levels[10] = 25;  // Congo alone
  Attributes a = decodeDmx(*p, mode, levels);
  EXPECT_FLOAT_EQ(a.color.r, 0.2f);
  EXPECT_FLOAT_EQ(a.color.g, 0.0f);
  EXPECT_FLOAT_EQ(a.color.b, 0.8f);
  // Congo behind half yellow: (0.2, 0, 0.8 * (1 - 0.6)) with yellow 153 = 0.6.
  levels[7] = 153;
  a = decodeDmx(*p, mode, levels);
  EXPECT_NEAR(a.color.b, 0.32f, 1e-6);
  // Red wheel behind full cyan: nothing passes.
  levels = spotLevels(255, 0, 0, 255, 0, 0, 0, 0);
  levels[10] = 15;
  EXPECT_EQ(decodeDmx(*p, mode, levels).color, glm::vec3(0.0f));
}

TEST(Decode, ShortFootprintReadsMissingSlotsAsZero) {
  const auto p = test::spotProfile();
  // Only Dimmer and Pan coarse/fine present: tilt reads 0 -> -135, zoom 0 -> 8.
  const std::vector<uint8_t> levels = {255, 0xFF, 0xFF};
  const Attributes a = decodeDmx(*p, p->modes[0], levels);
  EXPECT_FLOAT_EQ(a.intensity, 1.0f);
  EXPECT_FLOAT_EQ(a.panDeg, 270.0f);
  EXPECT_FLOAT_EQ(a.tiltDeg, -135.0f);
  EXPECT_FLOAT_EQ(*a.zoomDeg, 8.0f);
  EXPECT_NO_FATAL_FAILURE(decodeDmx(*p, p->modes[0], std::span<const uint8_t>()));
}

TEST(Decode, FractionOfMultiByteValues) {
  const uint8_t full[] = {255, 255, 255};
  EXPECT_FLOAT_EQ(dmxFraction(full), 1.0f);
  const uint8_t half[] = {0x80, 0x00};
  EXPECT_FLOAT_EQ(dmxFraction(half), 32768.0f / 65535.0f);
  EXPECT_FLOAT_EQ(dmxFraction(std::span<const uint8_t>()), 0.0f);
}

}  // namespace
}  // namespace haze
