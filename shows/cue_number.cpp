// Cue number comparison on the digits themselves: integer parts by length then digits (after
// leading zeros go), fractions digit by digit (after trailing zeros go).
#include "shows/cue_number.h"

#include <cassert>

namespace haze {

namespace {

bool allDigits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

struct Parts {
  std::string_view whole, fraction;
};

Parts split(std::string_view s) {
  Parts p;
  size_t dot = s.find('.');
  p.whole = s.substr(0, dot);
  p.fraction = dot == std::string_view::npos ? std::string_view{} : s.substr(dot + 1);
  while (p.whole.size() > 1 && p.whole.front() == '0') p.whole.remove_prefix(1);
  while (!p.fraction.empty() && p.fraction.back() == '0') p.fraction.remove_suffix(1);
  return p;
}

}  // namespace

bool isCueNumber(std::string_view s) {
  size_t dot = s.find('.');
  if (dot == std::string_view::npos) return allDigits(s);
  return allDigits(s.substr(0, dot)) && allDigits(s.substr(dot + 1));
}

int compareCueNumbers(std::string_view a, std::string_view b) {
  assert(isCueNumber(a) && isCueNumber(b) && "compareCueNumbers needs decimal strings: check isCueNumber first");
  Parts x = split(a), y = split(b);
  if (x.whole.size() != y.whole.size()) return x.whole.size() < y.whole.size() ? -1 : 1;
  if (int c = x.whole.compare(y.whole); c != 0) return c < 0 ? -1 : 1;
  // "5" < "55" < "6" digit by digit: a missing digit counts as 0, and trailing zeros are gone.
  int c = x.fraction.compare(y.fraction);
  return c < 0 ? -1 : (c > 0 ? 1 : 0);
}

}  // namespace haze
