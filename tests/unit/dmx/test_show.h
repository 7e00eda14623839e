// A small show built in code for the DMX input tests: profiles with hand-written DMX channels
// (so these tests do not depend on the profile loader), fixtures patched on universes 1 and 2.
#pragma once

#include <memory>

#include "fixtures/profile.h"
#include "shows/show.h"

namespace haze::test {

inline DmxChannel channel(const char* name, DmxAttribute a, float from = 0.0f, float to = 1.0f,
                          int byte = 0, int bytes = 1) {
  DmxChannel c;
  c.name = name;
  c.attribute = a;
  c.physicalFrom = from;
  c.physicalTo = to;
  c.byte = byte;
  c.bytes = bytes;
  return c;
}

// Spot, mode "Standard" (11 slots): Dimmer, Pan, Pan fine, Tilt, Tilt fine, Cyan, Magenta,
// Yellow, Gobo 1, Zoom, Strobe. Gobo slots: 0-9 Open, 10-19 Dots, 20-29 Stars, 30-255 Breakup.
inline std::shared_ptr<Profile> spotProfile() {
  auto p = std::make_shared<Profile>();
  p->name = "Test Spot";
  p->panDeg = {-270.0f, 270.0f};
  p->tiltDeg = {-135.0f, 135.0f};
  p->zoomDeg = {8.0f, 40.0f};
  p->colorMixing = ColorMixing::Cmy;
  p->goboWheels.push_back({"Gobo 1", {{"Open", {}, "", nullptr}, {"Dots", {}, "", nullptr},
                                      {"Stars", {}, "", nullptr}, {"Breakup", {}, "", nullptr}}});
  DmxMode m;
  m.name = "Standard";
  m.channels.push_back(channel("Dimmer", DmxAttribute::Intensity));
  m.channels.push_back(channel("Pan", DmxAttribute::Pan, -270, 270, 0, 2));
  m.channels.push_back(channel("Pan fine", DmxAttribute::Pan, -270, 270, 1, 2));
  m.channels.push_back(channel("Tilt", DmxAttribute::Tilt, -135, 135, 0, 2));
  m.channels.push_back(channel("Tilt fine", DmxAttribute::Tilt, -135, 135, 1, 2));
  m.channels.push_back(channel("Cyan", DmxAttribute::Cyan));
  m.channels.push_back(channel("Magenta", DmxAttribute::Magenta));
  m.channels.push_back(channel("Yellow", DmxAttribute::Yellow));
  DmxChannel gobo = channel("Gobo 1", DmxAttribute::Gobo);
  gobo.slotRanges = {{0, 9, 0}, {10, 19, 1}, {20, 29, 2}, {30, 255, 3}};
  m.channels.push_back(gobo);
  m.channels.push_back(channel("Zoom", DmxAttribute::Zoom, 8, 40));
  m.channels.push_back(channel("Strobe", DmxAttribute::None));
  p->modes.push_back(m);
  return p;
}

// LED par: mode "RGB" (3 slots, no dimmer) and mode "RGBW+Dimmer" (5 slots).
inline std::shared_ptr<Profile> parProfile() {
  auto p = std::make_shared<Profile>();
  p->name = "Test Par";
  p->colorMixing = ColorMixing::Rgb;
  DmxMode rgb;
  rgb.name = "RGB";
  rgb.channels = {channel("Red", DmxAttribute::Red), channel("Green", DmxAttribute::Green),
                  channel("Blue", DmxAttribute::Blue)};
  DmxMode rgbwd;
  rgbwd.name = "RGBW+Dimmer";
  rgbwd.channels = {channel("Dimmer", DmxAttribute::Intensity), channel("Red", DmxAttribute::Red),
                    channel("Green", DmxAttribute::Green), channel("Blue", DmxAttribute::Blue),
                    channel("White", DmxAttribute::White)};
  p->modes = {rgb, rgbwd};
  return p;
}

struct TestShow {
  Show show;
  ProfileSet profiles;
};

inline FixtureDef fixture(int id, const char* profile, const char* mode, int universe, int address) {
  FixtureDef f;
  f.id = id;
  f.name = "F" + std::to_string(id);
  f.profile = profile;
  f.mode = mode;
  if (universe > 0) f.patch = Patch{universe, address};
  return f;
}

// 101: spot at 1/1; 102: spot at 1/12; 201: par RGB at 2/1; 202: par at 2/510 (hangs over the
// universe's end); 301: spot without a patch.
inline TestShow makeTestShow() {
  TestShow t;
  t.profiles["spot"] = spotProfile();
  t.profiles["par"] = parProfile();
  t.show.fixtures = {fixture(101, "spot", "Standard", 1, 1), fixture(102, "spot", "Standard", 1, 12),
                     fixture(201, "par", "RGB", 2, 1), fixture(202, "par", "RGBW+Dimmer", 2, 510),
                     fixture(301, "spot", "Standard", 0, 0)};
  return t;
}

// A cue that sets fixture 101's intensity, with its fade and timecode ("" = none).
inline Cue intensityCue(const char* number, float intensity, double fadeS = 0.0, const char* timecode = "") {
  Cue c;
  c.number = number;
  c.fadeS = fadeS;
  c.timecode = timecode;
  c.values[101].intensity = intensity;
  return c;
}

// makeTestShow with cue list "Main": cues 1-3 set fixture 101 to 0.2, 0.4, 0.6 at timecodes
// 00:00:01:00 to 00:00:03:00 (fades of 0), cue 4 to 0.8 with no timecode.
inline TestShow timedShow() {
  TestShow t = makeTestShow();
  CueList l;
  l.name = "Main";
  l.cues = {intensityCue("1", 0.2f, 0.0, "00:00:01:00"), intensityCue("2", 0.4f, 0.0, "00:00:02:00"),
            intensityCue("3", 0.6f, 0.0, "00:00:03:00"), intensityCue("4", 0.8f)};
  t.show.cueLists.push_back(l);
  return t;
}

}  // namespace haze::test
