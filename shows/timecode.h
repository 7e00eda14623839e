// SMPTE timecode labels "hh:mm:ss:ff" (docs/show-format.md, cue "timecode"). A label is compared
// field by field, which orders them correctly at every frame rate (24, 25, 29.97 drop-frame,
// 30) without converting to seconds; seconds() is for measuring jumps.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace haze {

struct Timecode {
  int hours = 0, minutes = 0, seconds = 0, frames = 0;  // 0..23, 0..59, 0..59, 0..29
  auto operator<=>(const Timecode&) const = default;
  std::string str() const;  // "01:02:03:04"
  double toSeconds(double fps) const { return hours * 3600.0 + minutes * 60.0 + seconds + frames / fps; }
  // Whole frames since 00:00:00:00 at an integer rate (24, 25, 30: no drop-frame numbering).
  long toFrames(int fps) const { return (hours * 3600L + minutes * 60L + seconds) * fps + frames; }
  // The label of frame `count` at an integer rate; empty at or beyond 24 h.
  static std::optional<Timecode> fromFrames(long count, int fps);
};

// "hh:mm:ss:ff" (two digits each; ';' before the frames, the drop-frame spelling, is accepted)
// within a day; frames 0..29. Empty when the text is anything else.
std::optional<Timecode> parseTimecode(std::string_view text);

}  // namespace haze
