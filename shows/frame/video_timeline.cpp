#include "shows/frame/video_timeline.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "shows/cue_number.h"

namespace haze {

Result<CueTimeline> readTimeline(const std::filesystem::path& file, const Show& show, const CueList& list, double holdS) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{file.string(), "", "cannot open the timeline"};
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto bad = [&](const std::string& where, const std::string& what) { return Error{file.string(), where, what}; };
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return bad("", "not a JSON object");
  if (!doc.contains("go") || !doc["go"].is_array() || doc["go"].empty())
    return bad("/go", "expected a list of GOs: [{\"cue\": \"1\", \"at\": 0}, ...]");
  CueTimeline timeline;
  double last = 0.0;
  for (size_t i = 0; i < doc["go"].size(); ++i) {
    const auto& go = doc["go"][i];
    const std::string at = "/go/" + std::to_string(i);
    if (!go.is_object() || !go.contains("cue") || !go["cue"].is_string())
      return bad(at + "/cue", "expected a cue number as text (\"2\", \"4.5\")");
    if (!go.contains("at") || !go["at"].is_number() || go["at"].get<double>() < last)
      return bad(at + "/at", i == 0 ? "expected seconds >= 0" : "expected seconds, not before the GO before it");
    auto cue = findCue(list, go["cue"].get<std::string>());
    if (!cue) return bad(at + "/cue", cue.error().message);
    last = go["at"].get<double>();
    timeline.gos.push_back({.cueIndex = *cue, .atS = last});
    const Cue& c = list.cues[*cue];
    timeline.endS = std::max(timeline.endS, last + cueDurationS(show, c) + holdS);
  }
  if (doc.contains("end")) {
    if (!doc["end"].is_number() || doc["end"].get<double>() <= 0) return bad("/end", "expected seconds > 0");
    timeline.endS = doc["end"].get<double>();
  }
  return timeline;
}

VideoTimeline::VideoTimeline(const Show& show, const ProfileSet& profiles, const VideoPlan& plan)
    : plan_(plan),
      gos_(plan.timeline ? *plan.timeline : playCueRange(show, *plan.list, plan.from, plan.to, plan.holdS)),
      firstCue_(gos_.gos.empty() ? plan.from : gos_.gos.front().cueIndex),
      player_(show, profiles, *plan.list),
      heads_(show, profiles) {
  double lastTimedEndS = 0.0;  // seconds after the start
  if (plan_.timecodeStart) {
    live_.emplace(show, profiles, plan_.list);
    startFrame_ = plan_.timecodeStart->toFrames(plan_.timecodeRate);
    for (const Cue& c : plan_.list->cues)
      if (auto t = parseTimecode(c.timecode))
        lastTimedEndS = std::max(lastTimedEndS, static_cast<double>(t->toFrames(plan_.timecodeRate) - startFrame_) /
                                                        plan_.timecodeRate + cueDurationS(show, c));
  }
  endS_ = plan_.durationS > 0 ? plan_.durationS : live_ ? lastTimedEndS + plan_.holdS : gos_.endS;
  frames_ = std::max(1, static_cast<int>(std::ceil(endS_ * plan_.fps - 1e-9)));
  if (firstCue_ > 0) player_.jumpTo(firstCue_ - 1, 0.0);
  scheduleHazers(show, profiles);
}

std::optional<Timecode> VideoTimeline::timecodeAt(double timeS) const {
  return Timecode::fromFrames(startFrame_ + static_cast<long>(std::floor(timeS * plan_.timecodeRate + 1e-9)),
                              plan_.timecodeRate);
}

// The hazers go with the same GOs as the fixtures (docs/shows.md, "Hazers in cues"). Under
// timecode the GOs are where the firing rule changes the current cue: that rule is played once
// here without drawing, so there is one copy of it.
void VideoTimeline::scheduleHazers(const Show& show, const ProfileSet& profiles) {
  std::vector<HazerCue> onStage, gos;
  if (live_) {
    LivePlayback dry(show, profiles, plan_.list);
    std::optional<size_t> current;
    for (int f = 0; f < frames_; ++f) {
      const double t = static_cast<double>(f) / plan_.fps;
      const auto label = timecodeAt(t);
      if (!label) break;  // next() says so at that frame
      dry.timecode(*label, plan_.timecodeRate, t);
      const auto now = dry.currentCue();
      if (now && now != current) (f == 0 ? onStage : gos).push_back({plan_.list, *now, t});
      current = now;
    }
  } else {
    if (firstCue_ > 0) onStage.push_back({plan_.list, firstCue_ - 1, 0.0});
    for (const CueGo& g : gos_.gos) gos.push_back({plan_.list, g.cueIndex, g.atS});
  }
  hazers_ = hazerSchedule(show, onStage, gos);
}

Result<VideoTimeline::Frame> VideoTimeline::next() {
  Frame frame{.index = nextFrame_++};
  frame.timeS = static_cast<double>(frame.index) / plan_.fps;
  const double t = frame.timeS;
  if (live_) {
    const auto label = timecodeAt(t);
    if (!label)
      return Error{"", "", "timecode passes 24:00:00:00 at frame " + std::to_string(frame.index) +
                               "; use a shorter --duration"};
    frame.timecode = label;
    frame.fired = live_->timecode(*label, plan_.timecodeRate, t);
    frame.state = live_->stage(t, {}, {});
    frame.cue = live_->currentCue();
  } else {
    for (; nextGo_ < gos_.gos.size() && gos_.gos[nextGo_].atS <= t; ++nextGo_)
      if (!gos_.gos[nextGo_].byFollow) player_.gotoCue(gos_.gos[nextGo_].cueIndex, gos_.gos[nextGo_].atS);
    frame.state = player_.state(t);
    frame.cue = player_.currentCue();
  }
  // The command between frames is interpolated: a sampled fade.
  if (plan_.realMovement) {
    if (frame.index == 0) heads_.reset(frame.state, t);
    frame.state = heads_.advance(frame.state, t, true);
  }
  return frame;
}

}  // namespace haze
