// --play: parse LIST=CUE[@MASTER][+GO_S], then play the lists on one Playbacks on a schedule of
// GOs, sampled as `haze state --follow` samples one list.
#include "shows/frame/list_plays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "shows/cue_number.h"
#include "shows/movement.h"
#include "shows/playbacks.h"

namespace haze {

namespace {

std::optional<double> numberIn(const std::string& text, double lo, double hi) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
  return v;
}

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

Result<ListPlay> parseListPlay(const std::string& text) {
  const std::string need = "expected LIST=CUE[@MASTER][+GO_S], e.g. Main=2 or Specials=1@0.5+3";
  const size_t eq = text.rfind('=');
  if (eq == std::string::npos || eq == 0) return Error{"", "--play", "'" + text + "': " + need};
  ListPlay p;
  p.list = text.substr(0, eq);
  std::string rest = text.substr(eq + 1);
  if (const size_t plus = rest.find('+'); plus != std::string::npos) {
    const auto at = numberIn(rest.substr(plus + 1), 0.0, 1e9);
    if (!at) return Error{"", "--play", "'" + text + "': the GO time after '+' must be seconds, 0 or more; " + need};
    p.goAtS = *at;
    rest.resize(plus);
  }
  if (const size_t at = rest.find('@'); at != std::string::npos) {
    const auto master = numberIn(rest.substr(at + 1), 0.0, 1.0);
    if (!master) return Error{"", "--play", "'" + text + "': the master after '@' must be a level 0..1; " + need};
    p.master = *master;
    rest.resize(at);
  }
  if (!isCueNumber(rest)) return Error{"", "--play", "'" + text + "': '" + rest + "' is not a cue number; " + need};
  p.cue = rest;
  return p;
}

Result<StageState> playListsAt(const Show& show, const ProfileSet& profiles, const std::vector<ListPlay>& plays,
                               double atS, bool realMovement) {
  Playbacks playbacks(show, profiles);
  struct Go {
    size_t list;
    double atS;
  };
  std::vector<Go> gos;
  for (const ListPlay& play : plays) {
    const auto i = playbacks.find(play.list);
    if (!i) {
      std::string names;
      for (const CueList& l : show.cueLists) names += (names.empty() ? "\"" : ", \"") + l.name + "\"";
      return Error{show.file.string(), "--play", "no cue list \"" + play.list + "\"; the show's lists are " +
                                                     (names.empty() ? "none" : names)};
    }
    if (std::any_of(gos.begin(), gos.end(), [&](const Go& g) { return g.list == *i; }))
      return Error{show.file.string(), "--play", "cue list \"" + play.list + "\" is played twice; expected each list once"};
    const auto cue = findCue(playbacks.list(*i), play.cue);
    if (!cue) return Error{show.file.string(), "--play", cue.error().message};
    playbacks.setMaster(*i, play.master);
    if (*cue > 0) playbacks.jumpTo(*i, *cue - 1, 0.0);
    gos.push_back({*i, play.goAtS});
  }
  std::stable_sort(gos.begin(), gos.end(), [](const Go& a, const Go& b) { return a.atS < b.atS; });

  size_t done = 0;
  auto commandAt = [&](double t) {
    for (; done < gos.size() && gos[done].atS <= t; ++done) playbacks.go(gos[done].list, gos[done].atS);
    return playbacks.state(t);
  };
  if (!realMovement) return commandAt(atS);
  const double lastGoS = gos.empty() ? 0.0 : gos.back().atS;
  auto steady = [&](double t) {
    if (t < lastGoS || playbacks.nextFollowAtS()) return false;
    for (size_t i = 0; i < playbacks.size(); ++i)
      if (playbacks.fading(i, t)) return false;
    return true;
  };
  return followCommand(show, profiles, commandAt, steady, atS);
}

std::string describeListPlays(const std::vector<ListPlay>& plays) {
  std::string out;
  for (const ListPlay& p : plays) {
    out += (out.empty() ? "" : ", ") + p.list + " cue " + p.cue;
    if (p.master != 1.0) out += " at master " + shortNumber(p.master);
    if (p.goAtS != 0.0) out += " GO at " + shortNumber(p.goAtS) + " s";
  }
  return out;
}

HazerSchedule hazersOfPlays(const Show& show, const std::vector<ListPlay>& plays, bool timed) {
  std::vector<HazerCue> onStage, gos;
  for (const ListPlay& play : plays) {
    const CueList* list = show.findCueList(play.list);
    if (!list) continue;
    const auto cue = findCue(*list, play.cue);
    if (!cue) continue;
    if (!timed)
      onStage.push_back({list, *cue});
    else {
      if (*cue > 0) onStage.push_back({list, *cue - 1});
      gos.push_back({list, *cue, play.goAtS});
    }
  }
  return hazerSchedule(show, onStage, gos);
}

}  // namespace haze
