// Cue numbers between neighbours by exact decimal arithmetic on digit strings: scale both numbers
// to k fraction digits, and take the middle of the open interval for the smallest k that has one.
#include "shows/edit/edit_cue_number.h"

#include <algorithm>

#include "shows/cue_number.h"

namespace haze {

namespace {

// Cue numbers are short; anything past this many fraction digits is a pathological pair.
constexpr size_t kMaxFractionDigits = 12;

// A non-negative integer as decimal digits without leading zeros ("0" for zero).
std::string stripZeros(std::string s) {
  size_t i = s.find_first_not_of('0');
  return i == std::string::npos ? "0" : s.substr(i);
}

// The number times 10^k as an integer digit string (drops digits past k: callers pass k large enough
// or accept truncation, which is what flooring needs).
std::string scaled(std::string_view number, size_t k) {
  size_t dot = number.find('.');
  std::string whole(number.substr(0, dot));
  std::string frac = dot == std::string_view::npos ? "" : std::string(number.substr(dot + 1));
  frac.resize(k, '0');
  return stripZeros(whole + frac);
}

int compareInts(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
  return a.compare(b) < 0 ? -1 : (a == b ? 0 : 1);
}

std::string addOne(std::string s) {
  int i = static_cast<int>(s.size()) - 1;
  while (i >= 0 && s[i] == '9') s[i--] = '0';
  if (i < 0) return "1" + s;
  ++s[i];
  return s;
}

std::string subOne(std::string s) {  // s > 0
  int i = static_cast<int>(s.size()) - 1;
  while (s[i] == '0') s[i--] = '9';
  --s[i];
  return stripZeros(s);
}

std::string add(const std::string& a, const std::string& b) {
  std::string out;
  int carry = 0;
  for (size_t i = 0; i < std::max(a.size(), b.size()) || carry; ++i) {
    int d = carry;
    if (i < a.size()) d += a[a.size() - 1 - i] - '0';
    if (i < b.size()) d += b[b.size() - 1 - i] - '0';
    out.push_back(static_cast<char>('0' + d % 10));
    carry = d / 10;
  }
  std::reverse(out.begin(), out.end());
  return stripZeros(out);
}

std::string half(const std::string& s) {
  std::string out;
  int rem = 0;
  for (char c : s) {
    int d = rem * 10 + (c - '0');
    out.push_back(static_cast<char>('0' + d / 2));
    rem = d % 2;
  }
  return stripZeros(out);
}

// An integer scaled by 10^k back to a cue number ("15", 1 -> "1.5").
std::string unscale(const std::string& v, size_t k) {
  if (k == 0) return v;
  std::string padded = v.size() <= k ? std::string(k + 1 - v.size(), '0') + v : v;
  std::string whole = padded.substr(0, padded.size() - k);
  std::string frac = padded.substr(padded.size() - k);
  while (!frac.empty() && frac.back() == '0') frac.pop_back();
  return frac.empty() ? whole : whole + "." + frac;
}

// Significant fraction digits ("1.50" -> 1, "2" -> 0).
size_t fractionDigits(std::string_view number) {
  size_t dot = number.find('.');
  if (dot == std::string_view::npos) return 0;
  std::string_view frac = number.substr(dot + 1);
  while (!frac.empty() && frac.back() == '0') frac.remove_suffix(1);
  return frac.size();
}

}  // namespace

Result<std::string> cueNumberBetween(std::optional<std::string_view> before, std::optional<std::string_view> after) {
  for (auto n : {before, after})
    if (n && !isCueNumber(*n))
      return Error{"", "", "\"" + std::string(*n) + "\" is not a cue number; expected digits with an optional decimal part, like \"2\" or \"1.5\""};
  if (!after) return before ? add(scaled(*before, 0), "1") : std::string("1");
  std::string lowNumber = before ? std::string(*before) : "0";
  if (compareCueNumbers(lowNumber, *after) >= 0)
    return Error{"", "", before ? "no cue number fits between \"" + lowNumber + "\" and \"" + std::string(*after) +
                                      "\"; expected the first to come before the second"
                                : "no cue number fits ahead of cue \"" + std::string(*after) + "\"; cue numbers start at 0"};
  for (size_t k = 0; k <= kMaxFractionDigits; ++k) {
    // Open interval (low, high) at scale k: low floors, so +1 is the first number above it.
    std::string lo = addOne(scaled(lowNumber, k));
    std::string hiScaled = scaled(*after, k);
    // `after` is exact at scale k only when it has no more fraction digits; otherwise its floor is
    // already strictly below it and is the largest candidate.
    bool hiExact = fractionDigits(*after) <= k;
    std::string hi = hiExact ? (hiScaled == "0" ? std::string() : subOne(hiScaled)) : hiScaled;
    if (hi.empty() || compareInts(lo, hi) > 0) continue;
    return unscale(half(add(lo, hi)), k);
  }
  return Error{"", "", "no cue number with at most " + std::to_string(kMaxFractionDigits) + " decimals fits between \"" +
                           lowNumber + "\" and \"" + std::string(*after) + "\"; renumber the cues around it"};
}

}  // namespace haze
