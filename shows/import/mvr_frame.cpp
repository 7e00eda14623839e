// MVR's placement conventions (Z-up millimetres, {u}{v}{w}{o} matrices, absolute DMX
// addresses) turned into haze's (Y-up metres, Rz*Ry*Rx Euler angles, universe.address).
// Kept apart from the importer so the tests can check each rule on its own.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "shows/import/mvr_import.h"

namespace haze {

namespace {

// MVR world axis -> haze world axis, the GDTF map of docs/gdtf.md: (x, y, z) -> (x, z, -y).
const glm::dmat3 kMvrToHaze(1, 0, 0,    // column 0: image of MVR +X
                            0, 0, -1,   // column 1: image of MVR +Y is haze -Z
                            0, 1, 0);   // column 2: image of MVR +Z is haze +Y

bool parseNumber(const std::string& s, std::size_t& pos, double& out) {
  while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
  if (pos >= s.size()) return false;
  const char* begin = s.c_str() + pos;
  char* end = nullptr;
  out = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(out)) return false;
  pos += static_cast<std::size_t>(end - begin);
  return true;
}

}  // namespace

glm::vec3 mvrPointToHazeM(const glm::dvec3& mvrMm) {
  return glm::vec3(kMvrToHaze * mvrMm / 1000.0);
}

glm::vec3 mvrRotationToHazeDeg(const glm::dmat3& mvrRotation) {
  // The object's local frame is a GDTF frame, turned into haze's head frame by the same map, so
  // haze's rotation is the MVR one seen through the map on both sides.
  const glm::dmat3 r = kMvrToHaze * mvrRotation * glm::transpose(kMvrToHaze);
  // R = Rz(c) Ry(b) Rx(a): R[0][2] (column 0, row 2) = -sin b; row 2 = (-sb, cb sa, cb ca);
  // column 0 = (cc cb, sc cb, -sb).
  const double sb = std::clamp(-r[0][2], -1.0, 1.0);
  double a = 0.0, b = std::asin(sb), c = 0.0;
  if (std::abs(sb) < 0.999999) {
    a = std::atan2(r[1][2], r[2][2]);
    c = std::atan2(r[0][1], r[0][0]);
  } else {
    // Gimbal lock: only a +- c is defined; put it all in c (a = 0): R01 = -sin c, R11 = cos c.
    c = std::atan2(-r[1][0], r[1][1]);
  }
  const double toDeg = 180.0 / 3.14159265358979323846;
  auto tidyDeg = [&](double rad) {
    double d = rad * toDeg;
    d = std::round(d * 1e4) / 1e4;  // 1e-4 degree: keeps exact angles exact in the show file
    return d == 0.0 ? 0.0 : d;      // no "-0"
  };
  return glm::vec3(tidyDeg(a), tidyDeg(b), tidyDeg(c));
}

Result<glm::dmat4> parseMvrMatrix(const std::string& text) {
  double v[12];
  std::size_t pos = 0;
  for (int group = 0; group < 4; ++group) {
    while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    if (pos >= text.size() || text[pos] != '{')
      return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" is not {u1,u2,u3}{v1,v2,v3}{w1,w2,w3}{o1,o2,o3}"};
    ++pos;
    for (int i = 0; i < 3; ++i) {
      double x = 0.0;
      if (!parseNumber(text, pos, x))
        return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" has a missing or non-finite number; expected 12 numbers in 4 {} groups"};
      const double limit = group == 3 ? 1e9 : 1e3;  // origin in mm; axes near unit length
      if (std::abs(x) > limit)
        return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" has " + std::to_string(x) + ", outside the sane range +-" + std::to_string(limit)};
      v[group * 3 + i] = x;
      while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
      if (i < 2) {
        if (pos >= text.size() || text[pos] != ',')
          return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" lacks a comma between numbers"};
        ++pos;
      }
    }
    if (pos >= text.size() || text[pos] != '}')
      return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" lacks a closing }; expected 3 numbers per group"};
    ++pos;
  }
  while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
  if (pos != text.size())
    return Error{"", "", "Matrix \"" + text.substr(0, 80) + "\" has text after the 4th {} group"};
  glm::dmat4 m(1.0);
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 3; ++row) m[col][row] = v[col * 3 + row];
  return m;
}

Result<Patch> parseMvrAddress(const std::string& raw) {
  std::string text;
  for (char ch : raw)
    if (!std::isspace(static_cast<unsigned char>(ch))) text += ch;
  auto bad = [&](const std::string& why) {
    return Error{"", "", "Address \"" + raw.substr(0, 40) + "\" " + why +
                              "; expected an absolute address (1025 = universe 3 address 1) or UNIVERSE.ADDRESS"};
  };
  if (text.empty() || text.size() > 12) return bad("is empty or too long");
  auto number = [](const std::string& s, long long& out) {
    if (s.empty()) return false;
    for (char ch : s)
      if (ch < '0' || ch > '9') return false;
    out = std::stoll(s);
    return true;
  };
  Patch p;
  const auto dot = text.find('.');
  if (dot != std::string::npos) {
    long long u = 0, a = 0;
    if (!number(text.substr(0, dot), u) || !number(text.substr(dot + 1), a)) return bad("is not a number");
    if (u < 1 || u > 63999 || a < 1 || a > 512) return bad("is out of range (universe 1..63999, address 1..512)");
    p.universe = static_cast<int>(u);
    p.address = static_cast<int>(a);
    return p;
  }
  long long n = 0;
  if (!number(text, n)) return bad("is not a number");
  if (n == 0) {  // MVR writers use 0 for "not patched"
    p.universe = 0;
    p.address = 0;
    return p;
  }
  if (n > 63999LL * 512) return bad("is out of range");
  p.universe = static_cast<int>((n - 1) / 512 + 1);
  p.address = static_cast<int>((n - 1) % 512 + 1);
  return p;
}

}  // namespace haze
