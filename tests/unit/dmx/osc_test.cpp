// OSC remote-control messages: encoded here byte by byte from the OSC 1.0 specification
// (NUL-padded strings to 4 bytes, type tags, big-endian arguments), independently of liblo,
// then decoded by parseOscCommand into commands; malformed ones are refused with a reason.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "shows/dmx/osc_command.h"

namespace haze {
namespace {

struct Arg {
  char type;
  double number = 0;
  std::string text;
};

void pad(std::vector<uint8_t>& b, const std::string& s) {
  b.insert(b.end(), s.begin(), s.end());
  do b.push_back(0); while (b.size() % 4);
}

std::vector<uint8_t> osc(const std::string& address, const std::vector<Arg>& args = {}) {
  std::vector<uint8_t> b;
  pad(b, address);
  std::string tags = ",";
  for (const Arg& a : args) tags += a.type;
  pad(b, tags);
  for (const Arg& a : args) {
    auto be32 = [&](uint32_t v) { for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<uint8_t>(v >> s)); };
    if (a.type == 'i') be32(static_cast<uint32_t>(static_cast<int32_t>(a.number)));
    if (a.type == 'f') {
      const float f = static_cast<float>(a.number);
      uint32_t v;
      std::memcpy(&v, &f, 4);
      be32(v);
    }
    if (a.type == 's') pad(b, a.text);
  }
  return b;
}

TEST(Osc, TransportCommands) {
  EXPECT_EQ(parseOscCommand(osc("/haze/go")).command.kind, RemoteCommand::Kind::Go);
  EXPECT_EQ(parseOscCommand(osc("/haze/back")).command.kind, RemoteCommand::Kind::Back);
  EXPECT_EQ(parseOscCommand(osc("/haze/clear")).command.kind, RemoteCommand::Kind::ClearAll);
  const OscParse cue = parseOscCommand(osc("/haze/cue", {{'s', 0, "1.5"}}));
  ASSERT_TRUE(cue.ok) << cue.error;
  EXPECT_EQ(cue.command.kind, RemoteCommand::Kind::Goto);
  EXPECT_EQ(cue.command.cue, "1.5");
  EXPECT_EQ(parseOscCommand(osc("/haze/goto", {{'i', 3}})).command.cue, "3");
  EXPECT_EQ(parseOscCommand(osc("/haze/cue", {{'f', 2.5}})).command.cue, "2.5");
  EXPECT_EQ(parseOscCommand(osc("/haze/cue", {{'f', 4}})).command.cue, "4");
}

TEST(Osc, Camera) {
  const OscParse cam = parseOscCommand(osc("/haze/camera", {{'s', 0, "Side"}}));
  ASSERT_TRUE(cam.ok) << cam.error;
  EXPECT_EQ(cam.command.kind, RemoteCommand::Kind::Camera);
  EXPECT_EQ(cam.command.camera, "Side");
  for (const auto& bad : {osc("/haze/camera"), osc("/haze/camera", {{'i', 2}}),
                          osc("/haze/camera", {{'s', 0, "a"}, {'s', 0, "b"}})}) {
    const OscParse p = parseOscCommand(bad);
    EXPECT_FALSE(p.ok);
    EXPECT_NE(p.error.find("camera name"), std::string::npos) << p.error;
  }
}

TEST(Osc, ListCommands) {
  const OscParse go = parseOscCommand(osc("/haze/list/Specials/go"));
  ASSERT_TRUE(go.ok) << go.error;
  EXPECT_EQ(go.command.kind, RemoteCommand::Kind::ListGo);
  EXPECT_EQ(go.command.list, "Specials");
  EXPECT_EQ(parseOscCommand(osc("/haze/list/Main/back")).command.kind, RemoteCommand::Kind::ListBack);
  const OscParse m = parseOscCommand(osc("/haze/list/Specials/master", {{'f', 0.25}}));
  ASSERT_TRUE(m.ok) << m.error;
  EXPECT_EQ(m.command.kind, RemoteCommand::Kind::ListMaster);
  EXPECT_DOUBLE_EQ(m.command.level, 0.25);
  EXPECT_DOUBLE_EQ(parseOscCommand(osc("/haze/list/A/master", {{'i', 1}})).command.level, 1.0);
}

TEST(Osc, FixtureAttributes) {
  const OscParse i = parseOscCommand(osc("/haze/fixture/12/intensity", {{'f', 0.5}}));
  ASSERT_TRUE(i.ok) << i.error;
  EXPECT_EQ(i.command.kind, RemoteCommand::Kind::SetFixture);
  EXPECT_EQ(i.command.fixture, 12);
  EXPECT_FLOAT_EQ(*i.command.values.intensity, 0.5f);
  EXPECT_FALSE(i.command.values.panDeg);
  const OscParse pan = parseOscCommand(osc("/haze/fixture/1/pan", {{'i', -90}}));
  EXPECT_FLOAT_EQ(*pan.command.values.panDeg, -90.0f);
  const OscParse c = parseOscCommand(osc("/haze/fixture/1/color", {{'f', 1}, {'f', 0.25}, {'i', 0}}));
  ASSERT_TRUE(c.ok) << c.error;
  EXPECT_FLOAT_EQ(c.command.values.color->g, 0.25f);
  const OscParse g = parseOscCommand(osc("/haze/fixture/1/gobo", {{'s', 0, "Stars"}}));
  EXPECT_EQ(*g.command.values.gobo, "Stars");
  EXPECT_EQ(parseOscCommand(osc("/haze/fixture/1/clear")).command.kind, RemoteCommand::Kind::ClearFixture);
  // The lens's focus, 0..1 (docs/physics.md, "Focus").
  const OscParse f = parseOscCommand(osc("/haze/fixture/3/focus", {{'f', 0.25}}));
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_FLOAT_EQ(*f.command.values.gateFocus, 0.25f);
  EXPECT_FALSE(parseOscCommand(osc("/haze/fixture/3/focus", {{'f', 1.5}})).ok);
}

TEST(Osc, BadMessagesAreRefusedWithAReason) {
  auto refused = [](const std::vector<uint8_t>& b, const std::string& part) {
    const OscParse p = parseOscCommand(b);
    EXPECT_FALSE(p.ok);
    EXPECT_NE(p.error.find(part), std::string::npos) << p.error;
  };
  refused(osc("/haze/fixture/1/intensity", {{'f', 1.5}}), "0..1");
  refused(osc("/haze/fixture/1/intensity"), "one number");
  refused(osc("/haze/fixture/x/intensity", {{'f', 1}}), "not a fixture id");
  refused(osc("/haze/fixture/1/strobe", {{'f', 1}}), "unknown attribute");
  refused(osc("/haze/cue", {{'s', 0, "1.2.3"}}), "not a cue number");
  refused(osc("/haze/cue"), "one argument");
  refused(osc("/haze/go", {{'i', 1}}), "no arguments");
  refused(osc("/other/go"), "unknown address");
  refused(osc("/haze/list/A/master", {{'f', 1.5}}), "0..1");
  refused(osc("/haze/list/A/master"), "one number 0..1");
  refused(osc("/haze/list/A/go", {{'i', 1}}), "no arguments");
  refused(osc("/haze/list/A/stop"), "unknown list command");
  refused(osc("/haze/list//go"), "unknown address");
  refused(std::vector<uint8_t>{'#', 'b', 'u', 'n', 'd', 'l', 'e', 0, 0, 0, 0, 0, 0, 0, 0, 1}, "bundles");
  refused({}, "not an OSC message");
  auto cut = osc("/haze/fixture/1/intensity", {{'f', 1}});
  cut.resize(cut.size() - 2);  // the float runs past the end
  refused(cut, "well-formed");
  auto unpadded = osc("/haze/go");
  unpadded.pop_back();
  refused(unpadded, "well-formed");
}

TEST(Osc, RepliesAreOscMessages) {
  OscParse p = parseOscCommand(osc("/haze/go"));
  const std::vector<uint8_t> ok = oscReply(p);
  // "/haze/ok\0\0\0\0" ",s\0\0" "/haze/go\0\0\0\0"
  ASSERT_EQ(ok.size(), 12u + 4u + 12u);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(ok.data())), "/haze/ok");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(ok.data() + 12)), ",s");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(ok.data() + 16)), "/haze/go");
  p = parseOscCommand(osc("/haze/nope"));
  const std::vector<uint8_t> err = oscReply(p);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(err.data())), "/haze/error");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(err.data() + 12)), ",ss");
}

// Random bytes and mutated messages: refused or accepted, never a crash (ASan builds check reads).
TEST(Osc, RandomDatagramsNeverCrash) {
  std::mt19937 rng(5);
  const auto good = osc("/haze/fixture/3/color", {{'f', 1}, {'f', 0.5}, {'f', 0}});
  int accepted = 0;
  for (int i = 0; i < 20000; ++i) {
    std::vector<uint8_t> b = good;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits; ++k) {
      const size_t at = rng() % b.size();
      switch (rng() % 3) {
        case 0: b[at] = static_cast<uint8_t>(rng()); break;
        case 1: b.resize(at + 1); break;
        case 2: b.insert(b.begin() + static_cast<long>(at), static_cast<uint8_t>(rng())); break;
      }
    }
    const OscParse p = parseOscCommand(b);
    if (p.ok) ++accepted;
    else EXPECT_FALSE(p.error.empty());
    (void)oscReply(p);
  }
  EXPECT_GT(accepted, 0);
}

}  // namespace
}  // namespace haze
