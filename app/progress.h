// The progress line of a long job on stderr: "haze render: 120/900 frames (13 %), 3.1 frames/s,
// 4 min 12 s left", redrawn in place at most twice a second. Shown when stderr is a terminal or
// when asked (--progress); otherwise silent, so pipes and --json output stay clean.
#pragma once

#include <chrono>
#include <string>

namespace haze {

class Progress {
 public:
  // `unit` names what is counted ("frames", "cues", "rows"). force: --progress was given.
  Progress(std::string label, std::string unit, long total, bool force);
  ~Progress();  // ends the line if one was drawn

  void step(long done);
  // Ends the line (done or not); later steps draw nothing.
  void finish();
  bool shown() const { return enabled_; }

  // Whether stderr is a terminal: the default of every job's --progress.
  static bool stderrIsTerminal();

 private:
  void draw(long done, bool last);

  std::string label_, unit_;
  long total_;
  bool enabled_, terminal_, drawn_ = false;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

// "4 min 12 s", "12 s", "1 h 03 min".
std::string durationText(double seconds);

}  // namespace haze
