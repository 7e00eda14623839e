// CommandLine (see command_line.h): numbers are read whole with from_chars, so "12px" and
// "nan" are refused rather than read as 12 or as a number.
#include "app/command_line.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace haze {

namespace {

std::vector<std::string> splitNames(const std::string& names) {
  std::vector<std::string> out;
  std::stringstream in(names);
  for (std::string n; std::getline(in, n, '|');) out.push_back(n);
  return out;
}

bool wholeNumber(const std::string& s, double& out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

}  // namespace

CommandLine::CommandLine(std::string command, std::string usage)
    : command_(std::move(command)), usage_(std::move(usage)) {}

CommandLine& CommandLine::flag(const std::string& names, bool& dst) {
  options_.push_back({splitNames(names), false, "", [&dst](const std::string&) { return dst = true; }});
  return *this;
}

CommandLine& CommandLine::text(const std::string& names, std::string& dst, const std::string& need) {
  options_.push_back({splitNames(names), true, need, [&dst](const std::string& v) {
                        dst = v;
                        return true;
                      }});
  return *this;
}

CommandLine& CommandLine::choice(const std::string& names, std::string& dst, const std::vector<std::string>& choices) {
  std::string need;
  for (const std::string& c : choices) need += (need.empty() ? "" : " or ") + c;
  options_.push_back({splitNames(names), true, need, [&dst, choices](const std::string& v) {
                        for (const std::string& c : choices)
                          if (c == v) return dst = v, true;
                        return false;
                      }});
  return *this;
}

CommandLine& CommandLine::number(const std::string& names, double& dst, double lo, double hi, const std::string& need) {
  options_.push_back({splitNames(names), true, need, [&dst, lo, hi](const std::string& v) {
                        double x = 0.0;
                        if (!wholeNumber(v, x) || x < lo || x > hi) return false;
                        dst = x;
                        return true;
                      }});
  return *this;
}

CommandLine& CommandLine::integer(const std::string& names, int& dst, int lo, int hi, const std::string& need) {
  options_.push_back({splitNames(names), true, need, [&dst, lo, hi](const std::string& v) {
                        int x = 0;
                        const auto r = std::from_chars(v.data(), v.data() + v.size(), x);
                        if (r.ec != std::errc() || r.ptr != v.data() + v.size() || x < lo || x > hi) return false;
                        dst = x;
                        return true;
                      }});
  return *this;
}

CommandLine& CommandLine::custom(const std::string& names, const std::string& need,
                                 std::function<bool(const std::string&)> accept) {
  options_.push_back({splitNames(names), true, need, std::move(accept)});
  return *this;
}

CommandLine& CommandLine::positional(std::string& dst, const std::string& what, bool required) {
  positionals_.push_back({&dst, what, required});
  return *this;
}

const CommandLine::Option* CommandLine::find(const std::string& name) const {
  for (const Option& o : options_)
    for (const std::string& n : o.names)
      if (n == name) return &o;
  return nullptr;
}

int CommandLine::fail(const std::string& line) const {
  std::fprintf(stderr, "%s: %s\n", command_.c_str(), line.c_str());
  return kExitBadInput;
}

int CommandLine::usage(const std::string& line) const {
  std::fprintf(stderr, "%s: %s\n", command_.c_str(), line.c_str());
  return kExitUsage;
}

std::optional<CheckedShow> CommandLine::readShow(const std::string& file) const {
  CheckedShow checked = checkShowFile(file);
  for (const Error& e : checked.problems) fail(e.str());
  if (!checked.problems.empty()) return std::nullopt;
  return checked;
}

std::optional<int> CommandLine::parse(const Args& args) const {
  size_t nextPositional = 0;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::fputs(usage_.c_str(), stdout);
      return 0;
    }
    if (const Option* o = find(a)) {
      if (!o->takesValue) {
        o->set("");
        continue;
      }
      if (i + 1 >= args.size() || !o->set(args[i + 1])) return usage(a + " needs " + o->need);
      ++i;
      continue;
    }
    if (a.size() > 1 && a[0] == '-') return usage("unknown option '" + a + "' (see " + command_ + " --help)");
    if (nextPositional >= positionals_.size()) {
      const std::string what = positionals_.empty() ? "argument" : positionals_.back().what;
      return usage("unexpected argument '" + a + "' (one " + what + " at a time)");
    }
    *positionals_[nextPositional++].dst = a;
  }
  for (size_t k = nextPositional; k < positionals_.size(); ++k)
    if (positionals_[k].required)
      return usage("no " + positionals_[k].what + " given; " + usage_.substr(0, usage_.find('\n')));
  return std::nullopt;
}

}  // namespace haze
