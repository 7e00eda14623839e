// The command-line grammar of docs/gui.md, "Command line", as a recursive-descent parser over
// words. The same parser gives tab completion: wherever the words run out it notes what could
// have come next, so the candidates can never disagree with what the parser accepts.
#include "shows/edit/command_syntax.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "shows/cue_number.h"
#include "shows/palettes.h"

namespace haze {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// An integer word ("12"), no sign.
std::optional<int> integerWord(const CommandWord& w) {
  if (w.quoted || w.text.empty() || w.text.size() > 9) return std::nullopt;
  for (char c : w.text)
    if (!isDigit(c)) return std::nullopt;
  return std::atoi(w.text.c_str());
}

// A decimal number ("-30", "12.5").
std::optional<double> numberWord(const CommandWord& w) {
  if (w.quoted || w.text.empty()) return std::nullopt;
  size_t k = w.text[0] == '-' ? 1 : 0;
  bool digits = false, dot = false;
  for (; k < w.text.size(); ++k) {
    if (isDigit(w.text[k])) digits = true;
    else if (w.text[k] == '.' && !dot) dot = true;
    else return std::nullopt;
  }
  if (!digits) return std::nullopt;
  const double v = std::strtod(w.text.c_str(), nullptr);
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// The attributes the command line sets by name, with their unit and range as the show format has
// them (iris and frost are typed in percent like levels).
struct AttributeWord {
  const char* name;
  std::optional<float> CueValues::*member;
  double min, max, scale;
  const char* unit;
};
constexpr AttributeWord kAttributes[] = {
    {"pan", &CueValues::panDeg, -1e6, 1e6, 1.0, "degrees"},
    {"tilt", &CueValues::tiltDeg, -1e6, 1e6, 1.0, "degrees"},
    {"zoom", &CueValues::zoomDeg, 0.1, 179.0, 1.0, "degrees"},
    {"iris", &CueValues::iris, 0.0, 100.0, 0.01, "percent"},
    {"frost", &CueValues::frost, 0.0, 100.0, 0.01, "percent"},
    {"focus", &CueValues::gateFocus, 0.0, 100.0, 0.01, "percent"},
    {"cto", &CueValues::ctoMired, -500.0, 500.0, 1.0, "mired"},
};

// The words after which a number may be negative ("gobo rotation -45"), besides the attributes.
// (Times are never negative: keeping the sign gives the range error rather than "expected seconds".)
bool takesSignedNumber(const std::string& word) {
  return word == "rotation" || word == "spin" || word == "time" || word == "delay" || word == "follow" || word == "fade";
}

// Named colours for `color NAME`, as sRGB like a hex code: the gel colours a designer asks for.
struct NamedColor {
  const char* name;
  unsigned hex;
};
constexpr NamedColor kNamedColors[] = {
    {"white", 0xffffff}, {"red", 0xff0000},     {"green", 0x00ff00},    {"blue", 0x0000ff},
    {"cyan", 0x00ffff},  {"magenta", 0xff00ff}, {"yellow", 0xffff00},   {"amber", 0xffbf00},
    {"orange", 0xff8000}, {"pink", 0xff80c0},   {"lavender", 0xb080ff}, {"violet", 0x8000ff},
    {"congo", 0x4000c0}, {"straw", 0xfff0a0},   {"steel", 0xc0d8ff},
};

float srgbToLinear(unsigned byte) {
  const double c = byte / 255.0;
  return static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
}

glm::vec3 linearFromHex(unsigned hex) {
  return {srgbToLinear((hex >> 16) & 0xff), srgbToLinear((hex >> 8) & 0xff), srgbToLinear(hex & 0xff)};
}

// "#ff8800" (or "ff8800" after a '#' word) -> 0xff8800.
std::optional<unsigned> hexColor(const std::string& text) {
  const std::string digits = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (digits.size() != 6) return std::nullopt;
  unsigned v = 0;
  for (char c : digits) {
    const int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0'
                  : (c >= 'a' && c <= 'f')                    ? c - 'a' + 10
                  : (c >= 'A' && c <= 'F')                    ? c - 'A' + 10
                                                              : -1;
    if (d < 0) return std::nullopt;
    v = v * 16 + static_cast<unsigned>(d);
  }
  return v;
}

const AttributeWord* attributeNamed(const std::string& word) {
  for (const AttributeWord& a : kAttributes)
    if (word == a.name) return &a;
  return nullptr;
}

std::vector<std::string> settingWords() {
  std::vector<std::string> s = {"@", "palette"};
  for (const AttributeWord& a : kAttributes) s.push_back(a.name);
  for (const char* w : {"color", "colour", "gobo", "prism", "shutter", "strobe"}) s.push_back(w);
  return s;
}

std::string quoteIfSpaced(const std::string& name) {
  return name.find(' ') == std::string::npos ? name : "\"" + name + "\"";
}

class Parser {
 public:
  Parser(const Show& show, const std::vector<CommandWord>& words) : show_(show), w_(words) {}

  Result<ParsedCommand> line() {
    ParsedCommand c;
    if (atEnd()) {
      std::vector<std::string> start = {"group", "record", "update", "delete", "cue", "go", "clear", "label", "default"};
      for (const std::string& s : settingWords()) start.push_back(s);
      offer(start, "a fixture id");
      return c;
    }
    const std::string kw = word();
    if (kw == "record" || kw == "update" || kw == "delete") return recordUpdateDelete(kw, c);
    if (kw == "cue") {
      ++i_;
      if (Status s = cueRef(true, c); !s) return s.error();
      c.action = ParsedCommand::Action::GotoCue;
      if (Status s = cueTimes(c); !s) return s.error();
      if (Status s = end("the cue number"); !s) return s.error();
      return c;
    }
    if (kw == "label") return labelCue(c);
    if (kw == "default") return defaultFade(c);
    if (kw == "go" || kw == "clear") {
      ++i_;
      c.action = kw == "go" ? ParsedCommand::Action::Go : ParsedCommand::Action::Clear;
      if (Status s = end("'" + kw + "'"); !s) return s.error();
      return c;
    }
    if (kw == "group" || integerWord(w_[i_])) {
      auto sel = selection();
      if (!sel) return sel.error();
      c.selection = std::move(*sel);
    }
    if (!atEnd() && word() == "type") return changeType(c);
    if (Status s = settings(c); !s) return s.error();
    return c;
  }

  // What could follow when the words ran out (filled only then).
  std::vector<std::string> offered;
  std::string hint;
  bool reachedEnd = false;  // the words ran out where more could follow

 private:
  bool atEnd() const { return i_ >= w_.size(); }
  std::string word() const { return w_[i_].quoted ? std::string() : lower(w_[i_].text); }
  std::string previous() const { return i_ == 0 ? std::string() : "'" + w_[i_ - 1].text + "'"; }

  void offer(const std::vector<std::string>& words, const std::string& what) {
    if (!atEnd()) return;
    reachedEnd = true;
    offered.insert(offered.end(), words.begin(), words.end());
    if (hint.empty()) hint = what;
  }

  // "expected WHAT after 'PREV'" at the current word (or at the end of the line).
  Error expected(const std::string& what, const std::string& after) const {
    std::string where = after.empty() ? std::string() : " after " + after;
    if (atEnd()) return Error{"", "end of line", "expected " + what + where};
    return Error{"", "word " + std::to_string(w_[i_].position), "expected " + what + where + ", not '" + w_[i_].text + "'"};
  }
  Error unknown(const std::string& message) const {
    return Error{"", "word " + std::to_string(w_[i_].position), message};
  }

  Status keyword(const std::string& kw, const std::string& after) {
    offer({kw}, "'" + kw + "'");
    if (atEnd() || word() != kw) return expected("'" + kw + "'", after);
    ++i_;
    return Ok{};
  }

  Status end(const std::string& after) {
    if (atEnd()) return Ok{};
    return expected("the end of the line", after);
  }

  // CUE := [LIST '/'] NUMBER: the cue list by its number in the show (from 1; default the first),
  // as consoles write "cue 2/5".
  Status cueRef(bool existing, ParsedCommand& c) {
    std::vector<std::string> numbers;
    if (existing)
      for (size_t l = 0; l < show_.cueLists.size(); ++l)
        for (const Cue& q : show_.cueLists[l].cues)
          numbers.push_back(l == 0 ? q.number : std::to_string(l + 1) + "/" + q.number);
    offer(numbers, "a cue number");
    const std::string what = "a cue number (or LIST/NUMBER, as in 2/5)";
    if (atEnd() || w_[i_].quoted) return expected(what, "'cue'");
    std::string text = w_[i_].text;
    const size_t slash = text.find('/');
    if (slash != std::string::npos) {
      const auto list = integerWord(CommandWord{text.substr(0, slash), false, 0});
      if (!list || !isCueNumber(text.substr(slash + 1))) return expected(what, "'cue'");
      if (*list < 1 || static_cast<size_t>(*list) > show_.cueLists.size()) {
        std::string known;
        for (size_t l = 0; l < show_.cueLists.size(); ++l) known += (l ? ", " : "") + quoteIfSpaced(show_.cueLists[l].name);
        return unknown("there is no cue list " + std::to_string(*list) + "; the show has " +
                       std::to_string(show_.cueLists.size()) + (known.empty() ? "" : " (" + known + ")"));
      }
      c.cueList = static_cast<size_t>(*list - 1);
      text = text.substr(slash + 1);
    } else if (!isCueNumber(text)) {
      return expected(what, "'cue'");
    }
    c.cueNumber = text;
    ++i_;
    return Ok{};
  }

  // record (cue CUE | [KIND] palette NEW | group NEW), update (cue CUE | palette NAME),
  // delete (palette NAME | group NAME).
  Result<ParsedCommand> recordUpdateDelete(const std::string& kw, ParsedCommand& c) {
    ++i_;
    const bool rec = kw == "record", del = kw == "delete";
    std::vector<std::string> next;
    if (!del) next.push_back("cue");
    next.push_back("palette");
    if (kw != "update") next.push_back("group");
    if (rec) next.insert(next.end(), {"position", "color", "beam", "all"});
    offer(next, "");
    const std::string what = del ? "'palette' or 'group'"
                             : rec ? "'cue', 'palette', 'group' or a palette kind (position, color, beam, all)"
                                   : "'cue' or 'palette'";
    const std::string after = "'" + kw + "'";
    if (atEnd()) return expected(what, after);
    std::string sub = word();
    if (rec && sub != "cue" && sub != "palette" && sub != "group") {
      auto kind = paletteKindFromName(sub == "colour" ? "color" : sub);
      if (!kind) return expected(what, after);
      c.paletteKind = kind;
      ++i_;
      offer({"palette"}, "'palette'");
      if (atEnd() || word() != "palette") return expected("'palette'", previous());
      sub = "palette";
    }
    if (sub == "cue" && !del) {
      ++i_;
      if (Status s = cueRef(!rec, c); !s) return s.error();
      c.action = rec ? ParsedCommand::Action::Record : ParsedCommand::Action::Update;
      if (Status s = end("the cue number"); !s) return s.error();
      return c;
    }
    if (sub == "palette" || (sub == "group" && kw != "update")) {
      ++i_;
      if (rec) {
        offer({}, "the new " + sub + "'s name");
        if (atEnd()) return expected("a name for the new " + sub, "'" + sub + "'");
        for (; !atEnd(); ++i_) c.name += (c.name.empty() ? "" : " ") + w_[i_].text;
      } else {
        auto n = name(sub, "'" + sub + "'");
        if (!n) return n.error();
        c.name = sub == "palette" ? show_.palettes[*n].name : show_.groups[*n].name;
        if (Status s = end("the " + sub + "'s name"); !s) return s.error();
      }
      using A = ParsedCommand::Action;
      c.action = sub == "palette" ? (rec ? A::RecordPalette : del ? A::DeletePalette : A::UpdatePalette)
                                  : (rec ? A::RecordGroup : A::DeleteGroup);
      return c;
    }
    return expected(what, after);
  }

  // After `cue CUE`: ('time' | 'delay' | 'follow') SECONDS ..., 'follow off'; none: a GOTO.
  Status cueTimes(ParsedCommand& c) {
    bool any = false;
    while (true) {
      offer({"time", "delay", "follow"}, "");
      if (atEnd()) return Ok{};
      const std::string kw = word();
      if (kw != "time" && kw != "delay" && kw != "follow") {
        if (!any) return Ok{};  // end() names what was expected
        return expected("'time', 'delay', 'follow' or the end of the line", previous());
      }
      ++i_;
      if (kw == "follow") offer({"off"}, "seconds");
      else offer({}, "seconds");
      if (kw == "follow" && !atEnd() && word() == "off") {
        c.followS = std::optional<double>();
      } else {
        const auto typed = atEnd() ? std::nullopt : numberWord(w_[i_]);
        if (!typed) return expected(kw == "follow" ? "seconds or 'off'" : "seconds", "'" + kw + "'");
        const double v = *typed;
        if (v < 0.0 || v > 3600.0) return unknown(kw + " takes 0..3600 seconds, not " + w_[i_].text);
        if (kw == "time") c.fadeS = v;
        else if (kw == "delay") c.delayS = v;
        else c.followS.emplace(v);
      }
      ++i_;
      any = true;
      c.action = ParsedCommand::Action::CueTimes;
    }
  }

  // label cue CUE TEXT: the rest of the line (quoted or not) is the label; "" clears it.
  Result<ParsedCommand> labelCue(ParsedCommand& c) {
    ++i_;
    if (Status s = keyword("cue", "'label'"); !s) return s.error();
    if (Status s = cueRef(true, c); !s) return s.error();
    offer({}, "the label");
    if (atEnd()) return expected("the label (\"\" clears it)", "the cue number");
    for (; !atEnd(); ++i_) c.name += (c.name.empty() ? "" : " ") + w_[i_].text;
    c.action = ParsedCommand::Action::LabelCue;
    return c;
  }

  // default fade SECONDS: the fade every cue recorded from now on gets (Show::defaultFadeS).
  Result<ParsedCommand> defaultFade(ParsedCommand& c) {
    ++i_;
    if (Status s = keyword("fade", "'default'"); !s) return s.error();
    offer({}, "seconds");
    const auto v = atEnd() ? std::nullopt : numberWord(w_[i_]);
    if (!v) return expected("seconds", "'fade'");
    if (*v < 0.0 || *v > 3600.0) return unknown("a default fade takes 0..3600 seconds, not " + w_[i_].text);
    c.fadeS = *v;
    ++i_;
    c.action = ParsedCommand::Action::DefaultFade;
    if (Status s = end("the seconds"); !s) return s.error();
    return c;
  }

  // A number after `what`, in min..max.
  Result<float> numberIn(const std::string& what, double lo, double hi, const std::string& unit) {
    offer({}, "a number in " + unit);
    const auto v = atEnd() ? std::nullopt : numberWord(w_[i_]);
    if (!v) return expected("a number (" + unit + ")", "'" + what + "'");
    if (*v < lo || *v > hi) return unknown(what + " takes " + trim(lo) + ".." + trim(hi) + " " + unit + ", not " + w_[i_].text);
    ++i_;
    return static_cast<float>(*v);
  }

  // color (#RRGGBB | PALETTE | NAMED COLOUR | SLOT): a colour palette by name comes first, then
  // the named colours, then the fixture's colour wheel (checked when the line runs).
  Status color(ParsedCommand& c) {
    std::vector<std::string> names;
    for (const PaletteDef& p : show_.palettes)
      if (p.kind == PaletteKind::Color || p.kind == PaletteKind::All) names.push_back(quoteIfSpaced(p.name));
    for (const NamedColor& n : kNamedColors) names.push_back(n.name);
    offer(names, "#RRGGBB, a colour palette, a colour name or a colour wheel slot");
    if (atEnd()) return expected("#RRGGBB, a colour palette, a colour name or a colour wheel slot", previous());
    const std::string typed = w_[i_].text;
    if (!typed.empty() && typed[0] == '#') {
      const auto hex = hexColor(typed);
      if (!hex) return unknown("a colour code is # and six hex digits, as #ff8800; not '" + typed + "'");
      c.values.color = linearFromHex(*hex);
      ++i_;
      return Ok{};
    }
    for (const PaletteDef& p : show_.palettes)
      if ((p.kind == PaletteKind::Color || p.kind == PaletteKind::All) && lower(p.name) == lower(typed)) {
        c.palettes.push_back(p.name);
        ++i_;
        return Ok{};
      }
    for (const NamedColor& n : kNamedColors)
      if (lower(typed) == n.name) {
        c.values.color = linearFromHex(n.hex);
        ++i_;
        return Ok{};
      }
    c.colorSlot = typed;
    ++i_;
    return Ok{};
  }

  // gobo|prism (rotation DEGREES | spin DEGREES_PER_S | SLOT)
  Status wheel(const std::string& kw, ParsedCommand& c) {
    offer({"rotation", "spin", "open"}, "a " + kw + " name or number");
    if (atEnd()) return expected("a " + kw + " name or number, 'rotation' or 'spin'", "'" + kw + "'");
    const std::string sub = word();
    const bool gobo = kw == "gobo";
    if (sub == "rotation" || sub == "spin") {
      ++i_;
      const bool spin = sub == "spin";
      auto v = spin ? numberIn(kw + " spin", -36000.0, 36000.0, "degrees per second")
                    : numberIn(kw + " rotation", -1e6, 1e6, "degrees");
      if (!v) return v.error();
      if (gobo) (spin ? c.values.goboSpinDegS : c.values.goboRotationDeg) = *v;
      else (spin ? c.values.prismSpinDegS : c.values.prismRotationDeg) = *v;
      return Ok{};
    }
    (gobo ? c.goboSlot : c.prismSlot) = w_[i_].text;
    ++i_;
    return Ok{};
  }

  // shutter (open | closed)  |  strobe (HZ | off)
  Status shutter(const std::string& kw, ParsedCommand& c) {
    if (kw == "shutter") {
      offer({"open", "closed"}, "'open' or 'closed'");
      if (!atEnd() && (word() == "open" || word() == "closed")) {
        c.values.shutter = Shutter{.mode = word() == "open" ? ShutterMode::Open : ShutterMode::Closed};
        ++i_;
        return Ok{};
      }
      return expected("'open' or 'closed'", "'shutter'");
    }
    offer({"off"}, "flashes per second");
    if (!atEnd() && word() == "off") {
      c.values.shutter = Shutter{};
      ++i_;
      return Ok{};
    }
    auto hz = numberIn("strobe", kMinStrobeHz, kMaxStrobeHz, "Hz");
    if (!hz) return hz.error();
    c.values.shutter = Shutter{.mode = ShutterMode::Strobe, .rateHz = *hz, .duty = 0.5f};
    return Ok{};
  }

  // type TYPE ['mode' MODE]: words up to 'mode' (or one quoted name) each.
  Result<ParsedCommand> changeType(ParsedCommand& c) {
    ++i_;
    offer({}, "a fixture type, quoted (\"Robe Robin 600E Spot\")");
    auto words = [&](std::string& dst) {
      for (; !atEnd() && !(word() == "mode" && !dst.empty()); ++i_) dst += (dst.empty() ? "" : " ") + w_[i_].text;
    };
    words(c.name);
    if (c.name.empty()) return expected("a fixture type", "'type'");
    if (!atEnd()) {
      ++i_;  // 'mode'
      offer({}, "a mode of the new type, quoted");
      words(c.mode);
      if (c.mode.empty()) return expected("a mode", "'mode'");
    }
    c.action = ParsedCommand::Action::ChangeType;
    return c;
  }

  // selection := term (('+' | '-') term)*
  Result<std::vector<int>> selection() {
    auto first = term("");
    if (!first) return first.error();
    std::vector<int> ids = *first;
    while (true) {
      std::vector<std::string> next = {"+", "-"};
      if (lastTermWasId_) next.insert(next.begin(), "thru");
      for (const std::string& s : settingWords()) next.push_back(s);
      offer(next, "");
      if (atEnd()) break;
      const std::string op = word();
      if (op != "+" && op != "-") break;
      ++i_;
      auto more = term("'" + op + "'");
      if (!more) return more.error();
      if (op == "+") {
        ids.insert(ids.end(), more->begin(), more->end());
      } else {
        std::erase_if(ids, [&](int id) { return std::find(more->begin(), more->end(), id) != more->end(); });
      }
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.empty()) return Error{"", "selection", "the selection is empty: every fixture it named was taken out again"};
    return ids;
  }

  // term := ID ['thru' ID] | 'group' NAME
  Result<std::vector<int>> term(const std::string& after) {
    lastTermWasId_ = false;
    offer({"group"}, "a fixture id");
    if (atEnd()) return expected("a fixture id or 'group'", after);
    if (word() == "group") {
      ++i_;
      auto g = name("group", "'group'");
      if (!g) return g.error();
      return show_.groups[*g].fixtures;
    }
    const auto from = integerWord(w_[i_]);
    if (!from) return expected("a fixture id or 'group'", after);
    const size_t fromAt = i_++;
    if (!atEnd() && word() == "thru") {
      ++i_;
      offer({}, "a fixture id");
      if (atEnd() || !integerWord(w_[i_])) return expected("a number", "'thru'");
      const int to = *integerWord(w_[i_]);
      const int lo = std::min(*from, to), hi = std::max(*from, to);
      std::vector<int> ids;
      for (const FixtureDef& f : show_.fixtures)
        if (f.id >= lo && f.id <= hi) ids.push_back(f.id);
      if (ids.empty())
        return unknown("no fixture has an id from " + std::to_string(lo) + " to " + std::to_string(hi));
      ++i_;
      return ids;
    }
    lastTermWasId_ = true;
    if (!show_.findFixture(*from))
      return Error{"", "word " + std::to_string(w_[fromAt].position), "no fixture has id " + std::to_string(*from)};
    return std::vector<int>{*from};
  }

  // A group or palette: a quoted name, the longest run of words that is a name (any case), or
  // its number in the show's list (from 1). Returns the index.
  Result<size_t> name(const std::string& what, const std::string& after) {
    std::vector<std::string> names;
    if (what == "group")
      for (const GroupDef& g : show_.groups) names.push_back(g.name);
    else
      for (const PaletteDef& p : show_.palettes) names.push_back(p.name);
    std::vector<std::string> quoted;
    for (const std::string& n : names) quoted.push_back(quoteIfSpaced(n));
    offer(quoted, "a " + what + " name or number");
    if (atEnd()) return expected("a " + what + " name or number", after);
    for (size_t k = w_.size() - i_; k >= 1; --k) {
      if (k > 1 && std::any_of(w_.begin() + static_cast<long>(i_), w_.begin() + static_cast<long>(i_ + k),
                               [](const CommandWord& x) { return x.quoted; }))
        continue;
      std::string joined;
      for (size_t j = i_; j < i_ + k; ++j) joined += (j > i_ ? " " : "") + w_[j].text;
      for (size_t n = 0; n < names.size(); ++n)
        if (lower(names[n]) == lower(joined)) {
          i_ += k;
          return n;
        }
    }
    if (auto n = integerWord(w_[i_]); n && *n >= 1 && static_cast<size_t>(*n) <= names.size()) {
      ++i_;
      return static_cast<size_t>(*n - 1);
    }
    std::string known;
    for (size_t n = 0; n < names.size(); ++n) known += (n ? ", " : "") + quoted[n];
    if (integerWord(w_[i_]))
      return unknown("there is no " + what + " " + w_[i_].text + "; the show has " + std::to_string(names.size()) +
                     (names.empty() ? "" : " (" + known + ")"));
    return unknown("no " + what + " is named '" + w_[i_].text + "'" +
                   (names.empty() ? "; the show has none" : "; expected one of " + known));
  }

  // setting* := ('@' LEVEL | ATTRIBUTE NUMBER | 'palette' NAME)*
  Status settings(ParsedCommand& c) {
    bool any = false;
    while (true) {
      if (any) offer(settingWords(), "");
      if (atEnd()) break;
      const std::string kw = word();
      if (kw == "@") {
        ++i_;
        offer({"full", "out"}, "a level in percent");
        if (!atEnd() && word() == "full") c.values.intensity = 1.0f;
        else if (!atEnd() && word() == "out") c.values.intensity = 0.0f;
        else if (auto v = atEnd() ? std::nullopt : numberWord(w_[i_])) {
          if (*v < 0.0 || *v > 100.0) return unknown("a level is 0..100 percent, not " + w_[i_].text);
          c.values.intensity = static_cast<float>(*v / 100.0);
        } else {
          return expected("a level (0..100, 'full' or 'out')", "'@'");
        }
        ++i_;
      } else if (const AttributeWord* a = attributeNamed(kw)) {
        ++i_;
        offer({}, std::string("a number in ") + a->unit);
        const auto v = atEnd() ? std::nullopt : numberWord(w_[i_]);
        if (!v) return expected(std::string("a number (") + a->unit + ")", "'" + kw + "'");
        if (*v < a->min || *v > a->max)
          return unknown(std::string(a->name) + " takes " + trim(a->min) + ".." + trim(a->max) + " " + a->unit + ", not " +
                         w_[i_].text);
        c.values.*(a->member) = static_cast<float>(*v * a->scale);
        ++i_;
      } else if (kw == "palette") {
        ++i_;
        auto p = name("palette", "'palette'");
        if (!p) return p.error();
        c.palettes.push_back(show_.palettes[*p].name);
      } else if (kw == "color" || kw == "colour") {
        ++i_;
        if (Status s = color(c); !s) return s;
      } else if (kw == "gobo" || kw == "prism") {
        ++i_;
        if (Status s = wheel(kw, c); !s) return s;
      } else if (kw == "shutter" || kw == "strobe") {
        ++i_;
        if (Status s = shutter(kw, c); !s) return s;
      } else {
        std::string what = c.selection ? "'+', '-', " : "a fixture id, 'group', ";
        if (c.selection && lastTermWasId_ && !any) what += "'thru', ";
        what += "'@', 'palette' or an attribute (pan, tilt, zoom, iris, frost)";
        if (!c.selection && !any)
          return unknown("unknown command '" + w_[i_].text + "'; expected " + what +
                         ", or record, update, delete, cue, go, clear");
        return expected(what, previous());
      }
      any = true;
    }
    if (any) c.action = ParsedCommand::Action::Set;
    return Ok{};
  }

  static std::string trim(double v) {
    std::string s = std::to_string(v);
    while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) {
      const bool dot = s.back() == '.';
      s.pop_back();
      if (dot) break;
    }
    return s;
  }

  const Show& show_;
  const std::vector<CommandWord>& w_;
  size_t i_ = 0;
  bool lastTermWasId_ = false;
};

// Words and, when the line ends inside a quote, where that quote's text started.
struct Split {
  std::vector<CommandWord> words;
  std::vector<size_t> starts;  // offset of each word's first character (its quote for a quoted word)
  bool openQuote = false;
};

Split split(const std::string& line) {
  Split s;
  size_t k = 0;
  auto push = [&](std::string text, bool quoted, size_t start) {
    s.words.push_back(CommandWord{std::move(text), quoted, static_cast<int>(s.words.size()) + 1});
    s.starts.push_back(start);
  };
  while (k < line.size()) {
    const char c = line[k];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++k;
    } else if (c == '"') {
      const size_t close = line.find('"', k + 1);
      if (close == std::string::npos) {
        push(line.substr(k + 1), true, k);
        s.openQuote = true;
        break;
      }
      push(line.substr(k + 1, close - k - 1), true, k);
      k = close + 1;
    } else if (c == '@' || c == '+') {
      push(std::string(1, c), false, k);
      ++k;
    } else {
      const size_t start = k;
      std::string text;
      while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k])) && line[k] != '@' &&
             line[k] != '+' && line[k] != '"') {
        // "12-4": a minus between digits is a word of its own (a leading one is a sign).
        if (line[k] == '-' && !text.empty() && isDigit(text.back()) && k + 1 < line.size() && isDigit(line[k + 1])) break;
        text += line[k++];
      }
      push(text, false, start);
    }
  }
  return s;
}

// In a selection, "12 -4" means "12 - 4": the sign is split off when the word before it ends a
// term (a fixture id or a name), which the parser cannot see from the word alone. A negative
// number after an attribute keeps its sign.
std::vector<CommandWord> splitSelectionMinus(std::vector<CommandWord> words) {
  std::vector<CommandWord> out;
  for (size_t k = 0; k < words.size(); ++k) {
    const CommandWord& w = words[k];
    const bool afterAttribute = k > 0 && !words[k - 1].quoted &&
                                (attributeNamed(lower(words[k - 1].text)) || takesSignedNumber(lower(words[k - 1].text)));
    if (!w.quoted && w.text.size() > 1 && w.text[0] == '-' && isDigit(w.text[1]) && w.text.find('.') == std::string::npos &&
        !afterAttribute && k > 0 && lower(words[k - 1].text) != "@") {
      out.push_back(CommandWord{"-", false, w.position});
      out.push_back(CommandWord{w.text.substr(1), false, w.position});
    } else {
      out.push_back(w);
    }
  }
  return out;
}

}  // namespace

Result<std::vector<CommandWord>> splitCommandWords(const std::string& line) {
  Split s = split(line);
  if (s.openQuote)
    return Error{"", "word " + std::to_string(s.words.size()), "expected a closing '\"' after the name"};
  return splitSelectionMinus(std::move(s.words));
}

Result<ParsedCommand> parseCommand(const std::string& line, const Show& show) {
  auto words = splitCommandWords(line);
  if (!words) return words.error();
  Parser p(show, *words);
  return p.line();
}

Completion completeCommand(const std::string& partialLine, const Show& show) {
  Split s = split(partialLine);
  const bool partial = !s.words.empty() && (s.openQuote || !std::isspace(static_cast<unsigned char>(partialLine.back())));
  std::string prefix;
  if (partial) {
    prefix = lower(s.words.back().text);
    s.words.pop_back();
  }
  const std::vector<CommandWord> words = splitSelectionMinus(std::move(s.words));
  Parser p(show, words);
  Completion c;
  auto parsed = p.line();
  if (!parsed && !p.reachedEnd) {
    c.hint = parsed.error().str();
    return c;
  }
  for (const std::string& w : p.offered) {
    const std::string bare = lower(w.size() > 1 && w.front() == '"' ? w.substr(1, w.size() - 2) : w);
    if (bare.rfind(prefix, 0) == 0 && std::find(c.words.begin(), c.words.end(), w) == c.words.end()) c.words.push_back(w);
  }
  c.hint = p.hint;
  return c;
}

std::string applyCompletion(const std::string& partialLine, const Completion& completion) {
  if (completion.words.empty()) return partialLine;
  Split s = split(partialLine);
  const bool partial = !s.words.empty() && (s.openQuote || !std::isspace(static_cast<unsigned char>(partialLine.back())));
  const std::string head = partial ? partialLine.substr(0, s.starts.back()) : partialLine;
  if (completion.words.size() == 1) return head + completion.words.front() + " ";
  // Several: as far as they agree (in the first one's spelling), if that is longer than typed.
  std::string common = completion.words.front();
  for (const std::string& w : completion.words) {
    size_t n = 0;
    while (n < common.size() && n < w.size() && std::tolower(static_cast<unsigned char>(common[n])) ==
                                                    std::tolower(static_cast<unsigned char>(w[n])))
      ++n;
    common.resize(n);
  }
  const std::string typed = partial ? partialLine.substr(s.starts.back()) : std::string();
  return common.size() > typed.size() ? head + common : partialLine;
}

}  // namespace haze
