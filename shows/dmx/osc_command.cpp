// OSC messages to commands through liblo's deserialiser (it checks the padding, the type tags and
// that every argument fits in the datagram); the address space is matched here.
#include "shows/dmx/osc_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>

#include <lo/lo.h>

#include "shows/cue_number.h"

namespace haze {

namespace {

struct MessageFree {
  void operator()(lo_message m) const { lo_message_free(m); }
};
using Message = std::unique_ptr<std::remove_pointer_t<lo_message>, MessageFree>;

// A numeric argument of any OSC number type. liblo's arguments sit on 4-byte boundaries while
// lo_arg (it holds 64-bit members) wants 8, so they are copied out rather than read in place.
template <typename T>
T read(const lo_arg* a) {
  T v;
  std::memcpy(&v, reinterpret_cast<const unsigned char*>(a), sizeof v);
  return v;
}
std::optional<double> number(char type, const lo_arg* a) {
  switch (type) {
    case 'i': return read<int32_t>(a);
    case 'h': return static_cast<double>(read<int64_t>(a));
    case 'f': return read<float>(a);
    case 'd': return read<double>(a);
    default: return std::nullopt;
  }
}
const char* text(const lo_arg* a) { return reinterpret_cast<const char*>(a); }

std::vector<std::string> split(const std::string& address) {
  std::vector<std::string> parts;
  size_t at = 1;
  while (at <= address.size()) {
    const size_t next = address.find('/', at);
    parts.push_back(address.substr(at, next == std::string::npos ? std::string::npos : next - at));
    if (next == std::string::npos) break;
    at = next + 1;
  }
  return parts;
}

}  // namespace

OscParse parseOscCommand(std::span<const uint8_t> d) {
  OscParse r;
  auto fail = [&](std::string why) {
    r.ok = false;
    r.error = std::move(why);
    return r;
  };
  if (d.empty() || d.size() > 65507) return fail("not an OSC message: empty or oversized datagram");
  if (d.size() >= 8 && std::memcmp(d.data(), "#bundle", 8) == 0)
    return fail("OSC bundles are not accepted; send one message per datagram");
  if (d[0] != '/') return fail("not an OSC message: the address must start with '/'");
  std::vector<uint8_t> copy(d.begin(), d.end());  // liblo takes a non-const pointer
  // The address is the first NUL-terminated string (bounded by the datagram even when it is not
  // terminated), so a refusal can name it.
  r.address.assign(reinterpret_cast<const char*>(copy.data()),
                   strnlen(reinterpret_cast<const char*>(copy.data()), std::min<size_t>(copy.size(), 256)));
  int result = 0;
  Message m(lo_message_deserialise(copy.data(), copy.size(), &result));
  if (!m) return fail("not a well-formed OSC message (liblo error " + std::to_string(result) + ")");
  const int argc = lo_message_get_argc(m.get());
  const char* types = lo_message_get_types(m.get());
  lo_arg** argv = lo_message_get_argv(m.get());
  const std::string t = types ? types : "";
  const std::vector<std::string> parts = split(r.address);
  if (parts.size() < 2 || parts[0] != "haze") return fail("unknown address " + r.address + "; expected /haze/...");
  const std::string& verb = parts[1];
  if (parts.size() == 2 && (verb == "go" || verb == "back" || verb == "clear")) {
    if (argc != 0) return fail(r.address + " takes no arguments");
    r.command.kind = verb == "go" ? RemoteCommand::Kind::Go : verb == "back" ? RemoteCommand::Kind::Back : RemoteCommand::Kind::ClearAll;
    r.ok = true;
    return r;
  }
  if (parts.size() == 2 && verb == "camera") {
    if (argc != 1 || (t[0] != 's' && t[0] != 'S')) return fail(r.address + " takes one argument, a camera name (a string)");
    r.command.kind = RemoteCommand::Kind::Camera;
    r.command.camera = text(argv[0]);
    r.ok = true;
    return r;
  }
  if (parts.size() == 2 && (verb == "cue" || verb == "goto")) {
    if (argc != 1) return fail(r.address + " takes one argument, the cue number");
    std::string cue;
    if (t[0] == 's' || t[0] == 'S') {
      cue = text(argv[0]);
    } else if (auto v = number(t[0], argv[0]); v && *v >= 0 && *v < 1e9 && std::isfinite(*v)) {
      // A float cue number is taken to at most 3 decimals ("1.5"; 1.4999999 is 1.5).
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", *v);
      cue = text;
      while (cue.back() == '0') cue.pop_back();
      if (cue.back() == '.') cue.pop_back();
    }
    if (!isCueNumber(cue)) return fail(r.address + ": '" + cue + "' is not a cue number; expected one like 3 or 1.5");
    r.command.kind = RemoteCommand::Kind::Goto;
    r.command.cue = cue;
    r.ok = true;
    return r;
  }
  if (verb == "list" && parts.size() == 4 && !parts[2].empty()) {
    r.command.list = parts[2];
    const std::string& what = parts[3];
    if (what == "go" || what == "back") {
      if (argc != 0) return fail(r.address + " takes no arguments");
      r.command.kind = what == "go" ? RemoteCommand::Kind::ListGo : RemoteCommand::Kind::ListBack;
    } else if (what == "master") {
      const auto v = argc == 1 ? number(t[0], argv[0]) : std::nullopt;
      if (!v || !std::isfinite(*v) || *v < 0 || *v > 1)
        return fail(r.address + " takes one number 0..1, the master level (got type tags '" + t + "')");
      r.command.kind = RemoteCommand::Kind::ListMaster;
      r.command.level = *v;
    } else {
      return fail(r.address + ": unknown list command '" + what + "'; expected go, back or master");
    }
    r.ok = true;
    return r;
  }
  if (verb == "fixture" && parts.size() == 4) {
    const std::string& idText = parts[2];
    if (idText.empty() || idText.size() > 9 || idText.find_first_not_of("0123456789") != std::string::npos)
      return fail(r.address + ": '" + idText + "' is not a fixture id; expected a whole number");
    r.command.fixture = std::stoi(idText);
    const std::string& attr = parts[3];
    CueValues& v = r.command.values;
    auto one = [&](float lo, float hi, std::optional<float>& into) -> bool {
      if (argc != 1) return false;
      const auto x = number(t[0], argv[0]);
      if (!x || !std::isfinite(*x) || *x < lo || *x > hi) return false;
      into = static_cast<float>(*x);
      return true;
    };
    bool good = false;
    std::string expected;
    if (attr == "clear") {
      good = argc == 0;
      expected = "no arguments";
      r.command.kind = RemoteCommand::Kind::ClearFixture;
    } else if (attr == "intensity") {
      good = one(0, 1, v.intensity), expected = "one number 0..1";
    } else if (attr == "iris") {
      good = one(0, 1, v.iris), expected = "one number 0..1";
    } else if (attr == "focus") {
      good = one(0, 1, v.gateFocus), expected = "one number 0..1";
    } else if (attr == "pan") {
      good = one(-3600, 3600, v.panDeg), expected = "one number of degrees";
    } else if (attr == "tilt") {
      good = one(-3600, 3600, v.tiltDeg), expected = "one number of degrees";
    } else if (attr == "zoom") {
      good = one(0.1f, 180, v.zoomDeg), expected = "one field angle 0.1..180 degrees";
    } else if (attr == "gobo_rotation") {
      good = one(-36000, 36000, v.goboRotationDeg), expected = "one number of degrees per second";
    } else if (attr == "cto") {
      good = one(-500, 500, v.ctoMired), expected = "one number of mired";
    } else if (attr == "gobo2_rotation") {
      good = one(-36000, 36000, v.gobo2RotationDeg), expected = "one number of degrees";
    } else if (attr == "animation_rotation") {
      good = one(-36000, 36000, v.animationRotationDeg), expected = "one number of degrees";
    } else if (attr == "gobo_spin" || attr == "gobo2_spin" || attr == "prism_spin" || attr == "animation_spin") {
      auto& spin = attr == "gobo_spin"    ? v.goboSpinDegS
                   : attr == "gobo2_spin" ? v.gobo2SpinDegS
                   : attr == "prism_spin" ? v.prismSpinDegS
                                          : v.animationSpinDegS;
      good = one(-36000, 36000, spin), expected = "one number of degrees per second";
    } else if (attr == "color") {
      expected = "three numbers 0..1 (red, green, blue)";
      if (argc == 3) {
        float c[3];
        good = true;
        for (int i = 0; i < 3; ++i) {
          const auto x = number(t[static_cast<size_t>(i)], argv[i]);
          if (!x || !std::isfinite(*x) || *x < 0 || *x > 1) good = false;
          else c[i] = static_cast<float>(*x);
        }
        if (good) v.color = glm::vec3(c[0], c[1], c[2]);
      }
    } else if (attr == "gobo" || attr == "gobo2" || attr == "color2" || attr == "animation") {
      expected = "one string, the slot's name";
      if (argc == 1 && (t[0] == 's' || t[0] == 'S')) {
        (attr == "gobo" ? v.gobo : attr == "gobo2" ? v.gobo2 : attr == "animation" ? v.animation : v.color2) = std::string(text(argv[0]));
        good = true;
      }
    } else {
      return fail(r.address + ": unknown attribute '" + attr +
                  "'; expected intensity, pan, tilt, zoom, iris, focus, gobo, gobo_rotation, gobo2, gobo2_rotation, gobo_spin, "
                  "gobo2_spin, prism_spin, animation, animation_rotation, animation_spin, color, color2, cto or clear");
    }
    if (!good) return fail(r.address + " takes " + expected + " (got type tags '" + t + "')");
    if (attr != "clear") r.command.kind = RemoteCommand::Kind::SetFixture;
    r.ok = true;
    return r;
  }
  return fail("unknown address " + r.address +
              "; expected /haze/go, /haze/back, /haze/cue N, /haze/fixture/ID/ATTRIBUTE, /haze/clear or /haze/list/NAME/go|back|master");
}

std::vector<uint8_t> oscReply(const OscParse& p) {
  Message m(lo_message_new());
  if (!m) return {};
  const char* path = p.ok ? "/haze/ok" : "/haze/error";
  lo_message_add_string(m.get(), p.address.c_str());
  if (!p.ok) lo_message_add_string(m.get(), p.error.c_str());
  size_t size = 0;
  void* bytes = lo_message_serialise(m.get(), path, nullptr, &size);
  if (!bytes) return {};
  std::vector<uint8_t> out(static_cast<uint8_t*>(bytes), static_cast<uint8_t*>(bytes) + size);
  std::free(bytes);
  return out;
}

}  // namespace haze
