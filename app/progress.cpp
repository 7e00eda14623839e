#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace haze {

std::string durationText(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[48];
  if (s >= 3600)
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s / 60) % 60);
  else if (s >= 60)
    std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld s", s);
  return text;
}

bool Progress::stderrIsTerminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(std::string label, std::string unit, long total, bool force)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total),
      enabled_(force || stderrIsTerminal()), terminal_(stderrIsTerminal()),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

Progress::~Progress() { finish(); }

void Progress::step(long done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  // Twice a second on a terminal; a log file (--progress into a pipe) gets a line every 5 s.
  const auto every = terminal_ ? std::chrono::milliseconds(500) : std::chrono::milliseconds(5000);
  if (done < total_ && now - lastDraw_ < every) return;
  lastDraw_ = now;
  draw(done, done >= total_);
}

void Progress::draw(long done, bool last) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? done / elapsed : 0.0;
  const int percent = total_ > 0 ? static_cast<int>(100.0 * done / total_) : 100;
  std::string tail;
  if (last)
    tail = "done in " + durationText(elapsed);
  else if (rate > 0)
    tail = durationText((total_ - done) / rate) + " left";
  char line[256];
  std::snprintf(line, sizeof line, "%s: %ld/%ld %s (%d %%), %.2f %s/s, %s", label_.c_str(), done, total_,
                unit_.c_str(), percent, rate, unit_.c_str(), tail.c_str());
  // On a terminal the line is redrawn in place (\r, then clear to its end); elsewhere each
  // report is its own line.
  if (terminal_)
    std::fprintf(stderr, "\r%s\033[K", line);
  else
    std::fprintf(stderr, "%s\n", line);
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (enabled_ && drawn_ && terminal_) std::fputc('\n', stderr);
  enabled_ = false;
}

}  // namespace haze
