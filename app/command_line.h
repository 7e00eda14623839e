// The subcommands' command lines, read one way: named options (flags, text, a choice, numbers in
// a range), positional arguments, --help. A mistake is one line on stderr, "haze CMD: what",
// naming the option and what it needs, and the command exits kExitUsage (app/commands.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.h"
#include "shows/show_validate.h"

namespace haze {

class CommandLine {
 public:
  // `command` as in "haze render"; `usage` is printed as it is for --help / -h.
  CommandLine(std::string command, std::string usage);

  // `names` is one name or several separated by '|' ("-o|--output").
  CommandLine& flag(const std::string& names, bool& dst);
  CommandLine& text(const std::string& names, std::string& dst, const std::string& need);
  CommandLine& choice(const std::string& names, std::string& dst, const std::vector<std::string>& choices);
  CommandLine& number(const std::string& names, double& dst, double lo, double hi, const std::string& need);
  CommandLine& integer(const std::string& names, int& dst, int lo, int hi, const std::string& need);
  // Any other value: `accept` takes it (it may be called again, for a repeatable option) and
  // returns false when the value is not acceptable.
  CommandLine& custom(const std::string& names, const std::string& need, std::function<bool(const std::string&)> accept);
  // Positional arguments in order; `what` names one in errors ("show"). A missing required one
  // is an error, a second of the last kind is too.
  CommandLine& positional(std::string& dst, const std::string& what, bool required = true);

  // nullopt: go on with the command. A value: return it (0 after --help, else kExitUsage).
  std::optional<int> parse(const Args& args) const;
  // "haze CMD: line" on stderr; returns kExitBadInput (a file, a show, an output that failed).
  int fail(const std::string& line) const;
  // "haze CMD: line" on stderr; returns kExitUsage (options that do not go together).
  int usage(const std::string& line) const;
  // The show SHOW as `haze validate` checks it (shows/show_validate.h): every problem printed as
  // "haze CMD: <validate's line>" and nullopt, or the valid show with its profiles.
  std::optional<CheckedShow> readShow(const std::string& file) const;

 private:
  struct Option {
    std::vector<std::string> names;
    bool takesValue = false;
    std::string need;  // "--cue needs <need>"
    std::function<bool(const std::string&)> set;  // false: the value is not acceptable
  };
  struct Positional {
    std::string* dst;
    std::string what;
    bool required;
  };
  const Option* find(const std::string& name) const;

  std::string command_, usage_;
  std::vector<Option> options_;
  std::vector<Positional> positionals_;
};

}  // namespace haze
