// How hard each hazer runs over time (docs/shows.md, "Hazers in cues"): its output and its fan's
// speed as fractions of what the show's density section gives them, piecewise linear in the
// simulation's time. Cues make the keys (shows/hazer_levels.h); the simulation reads them at
// the middle of every step, so the same schedule gives the same field however it is reached.
#pragma once

#include <cstddef>
#include <vector>

namespace haze {

struct HazerLevel {
  float output = 1.0f;  // of the hazer's output, 0..1
  float fan = 1.0f;     // of its fan's speed, 0..1
  bool operator==(const HazerLevel&) const = default;
};

struct HazerKey {
  double timeS = 0.0;
  HazerLevel level;
  bool operator==(const HazerKey&) const = default;
};

class HazerSchedule {
 public:
  // Hazer h at time t: linear between its keys, held before the first and after the last; a
  // hazer without keys runs at full output and fan.
  HazerLevel at(size_t hazer, double timeS) const;
  // Whether any fan level changes over time (the air must then be recomputed as it goes).
  bool fansChange() const;
  // Hazer h is at `level` from the start (before any key).
  void hold(size_t hazer, HazerLevel level);
  // From goS, after delayS, over fadeS, hazer h goes from where it is then to `target`: the keys
  // after goS are dropped (a later GO takes over a running fade, as consoles do).
  void fade(size_t hazer, double goS, double delayS, double fadeS, HazerLevel target);
  bool empty() const { return keys_.empty(); }
  bool operator==(const HazerSchedule&) const = default;

 private:
  std::vector<std::vector<HazerKey>> keys_;  // per hazer, in time order
};

}  // namespace haze
