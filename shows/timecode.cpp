#include "shows/timecode.h"

#include <cstdio>

namespace haze {

std::string Timecode::str() const {
  char s[16];
  std::snprintf(s, sizeof s, "%02d:%02d:%02d:%02d", hours, minutes, seconds, frames);
  return s;
}

std::optional<Timecode> Timecode::fromFrames(long count, int fps) {
  if (count < 0 || fps <= 0 || count >= 86400L * fps) return std::nullopt;
  const long s = count / fps;
  return Timecode{static_cast<int>(s / 3600), static_cast<int>(s / 60 % 60), static_cast<int>(s % 60),
                  static_cast<int>(count % fps)};
}

std::optional<Timecode> parseTimecode(std::string_view t) {
  if (t.size() != 11) return std::nullopt;
  int v[4];
  for (int i = 0; i < 4; ++i) {
    const char a = t[static_cast<size_t>(3 * i)], b = t[static_cast<size_t>(3 * i + 1)];
    if (a < '0' || a > '9' || b < '0' || b > '9') return std::nullopt;
    v[i] = (a - '0') * 10 + (b - '0');
    if (i < 3) {
      const char sep = t[static_cast<size_t>(3 * i + 2)];
      if (sep != ':' && !(i == 2 && sep == ';')) return std::nullopt;
    }
  }
  if (v[0] > 23 || v[1] > 59 || v[2] > 59 || v[3] > 29) return std::nullopt;
  return Timecode{v[0], v[1], v[2], v[3]};
}

}  // namespace haze
