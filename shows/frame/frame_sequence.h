// Image sequences that many processes write together (docs/output.md, "Rendering on a cluster"):
// the frame number in a sequence's name, `--frames A-B` ranges, and which frames of a sequence
// are still missing. Pure: whether a file on disk is a complete image is the caller's to say
// (renderer/output/frame_files.h decodes it), so the scan is tested without images.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

// Frames first..last of a video, both included, counted from 0.
struct FrameRange {
  int first = 0;
  int last = 0;
  int count() const { return last - first + 1; }
  bool operator==(const FrameRange&) const = default;
};

// "A-B" (A <= B) or "A" alone; whole numbers from 0. The error says what was expected.
Result<FrameRange> parseFrameRange(const std::string& text);

// True when `out` names an image sequence: a printf-style frame number (%d, %05d) and .png or
// .exr. A '%' that is not one such number is an error (named in `error`).
bool isImageSequence(const std::filesystem::path& out, std::string& error);
// The file of frame `frame` of a sequence pattern that isImageSequence accepted.
std::filesystem::path sequenceFile(const std::filesystem::path& pattern, int frame);

// The frames 0..frames-1 of `pattern` whose file `complete` refuses (absent, truncated), in order.
std::vector<int> missingFrames(const std::filesystem::path& pattern, int frames,
                               const std::function<bool(const std::filesystem::path&)>& complete);

// Frame numbers in increasing order as runs: {0,1,2,7,9,10} -> "0-2, 7, 9-10" ("" when none).
std::string framesText(const std::vector<int>& frames);

}  // namespace haze
