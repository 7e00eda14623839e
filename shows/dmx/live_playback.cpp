// Live cue engine: OSC commands, timecode firing and chasing, DMX and programmer overlay.
#include "shows/dmx/live_playback.h"

#include <algorithm>

namespace haze {

namespace {
// Laying one set of values over another: the newer attribute wins.
void merge(CueValues& into, const CueValues& v) {
  if (v.intensity) into.intensity = v.intensity;
  if (v.panDeg) into.panDeg = v.panDeg;
  if (v.tiltDeg) into.tiltDeg = v.tiltDeg;
  if (v.zoomDeg) into.zoomDeg = v.zoomDeg;
  if (v.goboRotationDeg) into.goboRotationDeg = v.goboRotationDeg;
  if (v.iris) into.iris = v.iris;
  if (v.color) into.color = v.color;
  if (v.gobo) into.gobo = v.gobo;
}
}  // namespace

LivePlayback::LivePlayback(const Show& show, const ProfileSet& profiles, const CueList* list)
    : show_(show), profiles_(profiles), list_(list) {
  if (!list_) return;
  player_ = std::make_unique<CuePlayer>(show_, profiles_, *list_);
  for (size_t i = 0; i < list_->cues.size(); ++i)
    if (auto t = parseTimecode(list_->cues[i].timecode)) timed_.push_back({*t, i});
}

Result<std::string> LivePlayback::apply(const OscCommand& c, double nowS) {
  using K = OscCommand::Kind;
  if (c.kind == K::SetFixture || c.kind == K::ClearFixture) {
    if (std::none_of(show_.fixtures.begin(), show_.fixtures.end(), [&](const FixtureDef& f) { return f.id == c.fixture; }))
      return Error{"", "fixture " + std::to_string(c.fixture), "the show has no fixture with this id"};
    if (c.kind == K::ClearFixture) programmer_.erase(c.fixture);
    else merge(programmer_[c.fixture], c.values);
    return std::string("fixture ") + std::to_string(c.fixture);
  }
  if (c.kind == K::Camera) {
    if (std::none_of(show_.cameras.begin(), show_.cameras.end(), [&](const CameraDef& cam) { return cam.name == c.camera; })) {
      std::string names;
      for (const CameraDef& cam : show_.cameras) names += (names.empty() ? "" : ", ") + ("\"" + cam.name + "\"");
      return Error{"", "camera \"" + c.camera + "\"",
                   "the show has no camera with this name" + (names.empty() ? std::string(" (it has none)") : "; it has " + names)};
    }
    camera_ = c.camera;
    return "camera \"" + camera_ + "\"";
  }
  if (c.kind == K::ClearAll) {
    programmer_.clear();
    return std::string("programmer cleared");
  }
  if (!player_) return Error{"", "cue list", "the show has no cue list to play"};
  const std::string listName = list_->name.empty() ? "the cue list" : "cue list \"" + list_->name + "\"";
  switch (c.kind) {
    case K::Go:
      if (!player_->go(nowS)) return Error{"", "GO", "no cue after the current one in " + listName};
      break;
    case K::Back:
      if (!player_->back(nowS)) return Error{"", "BACK", "no cue before the current one in " + listName};
      break;
    case K::Goto: {
      auto index = findCue(*list_, c.cue);
      if (!index) return index.error();
      player_->gotoCue(*index, nowS);
      break;
    }
    default: break;
  }
  return "cue " + list_->cues[*player_->currentCue()].number;
}

std::string LivePlayback::chase(const Timecode& time, double nowS) {
  std::optional<size_t> target;
  for (const auto& [t, index] : timed_)
    if (t <= time) target = index;
  if (target) {
    if (player_->currentCue() == target) return "";
    player_->jumpTo(*target, nowS);
    return "chased to cue " + list_->cues[*target].number;
  }
  if (!player_->currentCue()) return "";
  player_ = std::make_unique<CuePlayer>(show_, profiles_, *list_);
  return "before the first timed cue: the stage at its defaults";
}

std::string LivePlayback::timecode(const Timecode& time, double fps, double nowS) {
  if (!player_ || timed_.empty()) return "";
  const double seconds = time.toSeconds(fps);
  std::string fired;
  if (lastTime_ && seconds >= lastSeconds_ && seconds - lastSeconds_ <= 1.0) {
    for (const auto& [t, index] : timed_) {
      if (*lastTime_ < t && t <= time) {
        player_->gotoCue(index, nowS);
        fired += (fired.empty() ? "fired cue " : ", cue ") + list_->cues[index].number;
      }
    }
  } else {
    fired = chase(time, nowS);
  }
  lastTime_ = time;
  lastSeconds_ = seconds;
  return fired;
}

StageState LivePlayback::stage(double nowS, const StageState& dmx, const std::set<int>& dmxFixtures) {
  StageState s = player_ ? player_->state(nowS) : defaultState(show_);
  for (int id : dmxFixtures)
    if (auto it = dmx.find(id); it != dmx.end()) s[id] = it->second;
  for (const auto& [id, v] : programmer_)
    if (auto it = s.find(id); it != s.end()) overlayValues(it->second, v);
  return s;
}

}  // namespace haze
