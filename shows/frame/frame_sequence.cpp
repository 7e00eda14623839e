#include "shows/frame/frame_sequence.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iterator>
#include <regex>

namespace haze {
namespace {

const std::regex& framePattern() {
  static const std::regex r("%0?[0-9]*d");
  return r;
}

// A whole number from 0 that fills `text` exactly (no sign, no spaces), below 10^9.
bool wholeNumber(std::string_view text, int& out) {
  if (text.empty() || text.size() > 9) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && out >= 0;
}

}  // namespace

Result<FrameRange> parseFrameRange(const std::string& text) {
  const auto dash = text.find('-');
  FrameRange r;
  const bool ok = dash == std::string::npos
                      ? wholeNumber(text, r.first) && (r.last = r.first, true)
                      : wholeNumber(std::string_view(text).substr(0, dash), r.first) &&
                            wholeNumber(std::string_view(text).substr(dash + 1), r.last);
  if (!ok) return Error{"", "", "--frames: expected A-B or A, frame numbers from 0 (got '" + text + "')"};
  if (r.first > r.last) return Error{"", "", "--frames: the first frame comes after the last (got '" + text + "')"};
  return r;
}

bool isImageSequence(const std::filesystem::path& out, std::string& error) {
  const std::string name = out.filename().string();
  if (name.find('%') == std::string::npos) return false;
  const auto count = std::distance(std::sregex_iterator(name.begin(), name.end(), framePattern()), std::sregex_iterator());
  const auto percents = std::count(name.begin(), name.end(), '%');
  const std::string ext = out.extension().string();
  if (count != 1 || percents != 1)
    error = "an image sequence needs one frame number in its name, like OUT-%05d.png";
  else if (ext != ".png" && ext != ".exr")
    error = "an image sequence is .png or .exr (got '" + ext + "')";
  return true;
}

std::filesystem::path sequenceFile(const std::filesystem::path& pattern, int frame) {
  const std::string name = pattern.filename().string();
  std::smatch m;
  std::regex_search(name, m, framePattern());
  char number[32];
  std::snprintf(number, sizeof number, m.str().c_str(), frame);
  return pattern.parent_path() / (m.prefix().str() + number + m.suffix().str());
}

std::vector<int> missingFrames(const std::filesystem::path& pattern, int frames,
                               const std::function<bool(const std::filesystem::path&)>& complete) {
  std::vector<int> missing;
  for (int f = 0; f < frames; ++f)
    if (!complete(sequenceFile(pattern, f))) missing.push_back(f);
  return missing;
}

std::string framesText(const std::vector<int>& frames) {
  std::string text;
  for (size_t i = 0; i < frames.size();) {
    size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    if (!text.empty()) text += ", ";
    text += std::to_string(frames[i]);
    if (j > i) text += "-" + std::to_string(frames[j]);
    i = j + 1;
  }
  return text;
}

}  // namespace haze
