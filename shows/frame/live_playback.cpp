// Live cue engine: OSC commands, timecode firing and chasing, DMX and programmer overlay.
#include "shows/frame/live_playback.h"

#include <algorithm>
#include <cstdio>

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
  if (v.gobo2) into.gobo2 = v.gobo2;
  if (v.color2) into.color2 = v.color2;
  if (v.ctoMired) into.ctoMired = v.ctoMired;
  if (v.gobo2RotationDeg) into.gobo2RotationDeg = v.gobo2RotationDeg;
  if (v.goboSpinDegS) into.goboSpinDegS = v.goboSpinDegS;
  if (v.gobo2SpinDegS) into.gobo2SpinDegS = v.gobo2SpinDegS;
  if (v.prismSpinDegS) into.prismSpinDegS = v.prismSpinDegS;
  if (v.animation) into.animation = v.animation;
  if (v.animationRotationDeg) into.animationRotationDeg = v.animationRotationDeg;
  if (v.animationSpinDegS) into.animationSpinDegS = v.animationSpinDegS;
  if (v.gateFocus) into.gateFocus = v.gateFocus;
}
}  // namespace

LivePlayback::LivePlayback(const Show& show, const ProfileSet& profiles, const CueList* list)
    : show_(show), list_(list), playbacks_(show, profiles) {
  if (!list_) return;
  // Cue list names are unique in a show (loadShow refuses repeats).
  const auto i = playbacks_.find(list_->name);
  if (!i) {
    list_ = nullptr;
    return;
  }
  main_ = *i;
  list_ = &playbacks_.list(main_);
  for (size_t i = 0; i < list_->cues.size(); ++i)
    if (auto t = parseTimecode(list_->cues[i].timecode)) timed_.push_back({*t, i});
}

Result<std::string> LivePlayback::apply(const RemoteCommand& c, double nowS) {
  using K = RemoteCommand::Kind;
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
  if (c.kind == K::ListGo || c.kind == K::ListBack || c.kind == K::ListMaster) {
    const auto i = playbacks_.find(c.list);
    if (!i) {
      std::string names;
      for (const CueList& l : show_.cueLists) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
      return Error{"", "cue list", "the show has no cue list \"" + c.list + "\"; its lists are " +
                                       (names.empty() ? "none" : names)};
    }
    const std::string name = "cue list \"" + c.list + "\"";
    if (c.kind == K::ListMaster) {
      playbacks_.setMaster(*i, c.level);
      char level[32];
      std::snprintf(level, sizeof level, "%g", playbacks_.master(*i));
      return name + ": master " + level;
    }
    if (c.kind == K::ListGo && !playbacks_.go(*i, nowS))
      return Error{"", "GO", "no cue after the current one in " + name};
    if (c.kind == K::ListBack && !playbacks_.back(*i, nowS))
      return Error{"", "BACK", "no cue before the current one in " + name};
    return name + ": cue " + playbacks_.list(*i).cues[*playbacks_.currentCue(*i)].number;
  }
  if (!list_) return Error{"", "cue list", "the show has no cue list to play"};
  const std::string listName = list_->name.empty() ? "the cue list" : "cue list \"" + list_->name + "\"";
  switch (c.kind) {
    case K::Go:
      if (!playbacks_.go(main_, nowS)) return Error{"", "GO", "no cue after the current one in " + listName};
      break;
    case K::Back:
      if (!playbacks_.back(main_, nowS)) return Error{"", "BACK", "no cue before the current one in " + listName};
      break;
    case K::Goto: {
      auto index = findCue(*list_, c.cue);
      if (!index) return index.error();
      playbacks_.gotoCue(main_, *index, nowS);
      break;
    }
    default: break;
  }
  return "cue " + list_->cues[*playbacks_.currentCue(main_)].number;
}

std::string LivePlayback::chase(const Timecode& time, double nowS) {
  std::optional<size_t> target;
  for (const auto& [t, index] : timed_)
    if (t <= time) target = index;
  if (target) {
    if (playbacks_.currentCue(main_) == target) return "";
    playbacks_.jumpTo(main_, *target, nowS);
    return "chased to cue " + list_->cues[*target].number;
  }
  if (!playbacks_.currentCue(main_)) return "";
  playbacks_.release(main_);
  return "before the first timed cue: the stage at its defaults";
}

std::string LivePlayback::timecode(const Timecode& time, double fps, double nowS) {
  if (!list_ || timed_.empty()) return "";
  const double seconds = time.toSeconds(fps);
  std::string fired;
  if (lastTime_ && seconds >= lastSeconds_ && seconds - lastSeconds_ <= 1.0) {
    for (const auto& [t, index] : timed_) {
      if (*lastTime_ < t && t <= time) {
        playbacks_.gotoCue(main_, index, nowS);
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
  StageState s = playbacks_.state(nowS);  // every list merged; defaults where none plays
  for (int id : dmxFixtures)
    if (auto it = dmx.find(id); it != dmx.end()) s[id] = it->second;
  for (const auto& [id, v] : programmer_)
    if (auto it = s.find(id); it != s.end()) overlayValues(it->second, v);
  return s;
}

}  // namespace haze
