// placeLabels, patchText, listedFixtures (see label_layout.h).
#include "shows/edit/label_layout.h"

#include <algorithm>
#include <cctype>

namespace haze {

namespace {

constexpr float kMarkerGapPx = 11.0f;  // from the marker's centre to the label: clear of its 9 px ring
constexpr float kStackGapPx = 2.0f;    // between labels pushed under one another

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::vector<PlacedLabel> placeLabels(const std::vector<LabelRequest>& labels, float maxPushPx) {
  std::vector<PlacedLabel> placed;
  placed.reserve(labels.size());
  for (const LabelRequest& r : labels) {
    const LabelBox first{r.anchor.x + kMarkerGapPx, r.anchor.y - r.sizePx.y * 0.5f, r.sizePx.x, r.sizePx.y};
    const float step = std::max(r.sizePx.y, 1.0f) + kStackGapPx;
    LabelBox box = first;
    // Each step clears at least the label it met (a push never lands on the same box twice), so
    // the loop ends after at most one step per label placed plus the overlap's own height.
    for (bool clear = false; !clear && box.y - first.y <= maxPushPx;) {
      clear = true;
      for (const PlacedLabel& p : placed)
        if (box.intersects(p.box)) {
          // Straight under the box it meets, not only a step down: fewer passes, same result.
          box.y = std::max(box.y + step, p.box.y + p.box.h + kStackGapPx);
          clear = false;
          break;
        }
    }
    if (box.y - first.y > maxPushPx) box = first;
    placed.push_back({.fixture = r.fixture, .anchor = r.anchor, .box = box, .moved = box.y != first.y});
  }
  return placed;
}

std::string patchText(const FixtureDef& f) {
  return f.patch ? std::to_string(f.patch->universe) + "." + std::to_string(f.patch->address) : "-";
}

std::vector<const FixtureDef*> listedFixtures(const Show& show, const std::string& filter) {
  const size_t from = filter.find_first_not_of(" \t");
  const std::string want = from == std::string::npos ? "" : lower(filter.substr(from, filter.find_last_not_of(" \t") + 1 - from));
  std::vector<const FixtureDef*> out;
  for (const FixtureDef& f : show.fixtures) {
    if (!want.empty()) {
      const std::string text = lower(std::to_string(f.id) + "\n" + f.name + "\n" + f.profile + "\n" + f.mode + "\n" + patchText(f));
      if (text.find(want) == std::string::npos) continue;
    }
    out.push_back(&f);
  }
  std::stable_sort(out.begin(), out.end(), [](const FixtureDef* a, const FixtureDef* b) { return a->id < b->id; });
  return out;
}

}  // namespace haze
