// runCommandLine: resolves everything a parsed line needs (the fixtures, the palettes' values for
// each of them, where a recorded cue goes) before it runs one edit, so that a line that cannot be
// done fails before anything changed.
#include "shows/edit/command_run.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "fixtures/fixture_library.h"
#include "shows/cue_number.h"
#include "shows/id_ranges.h"
#include "shows/edit/command_syntax.h"
#include "shows/edit/edit_defaults.h"
#include "shows/palettes.h"
#include "shows/playback.h"

namespace haze {

namespace {

// One command line's edit in the undo history, named by what was typed.
class CommandLineEdit final : public EditCommand {
 public:
  CommandLineEdit(std::string line, std::unique_ptr<EditCommand> inner) : line_(std::move(line)), inner_(std::move(inner)) {}
  std::string label() const override { return "Command \"" + line_ + "\""; }
  Status apply(EditTarget& t) override { return inner_->apply(t); }
  void undo(EditTarget& t) override { inner_->undo(t); }

 private:
  std::string line_;
  std::unique_ptr<EditCommand> inner_;
};

std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::string percent(float v) {
  std::ostringstream o;
  o << std::round(v * 1000.0f) / 10.0f;
  return o.str();
}

std::string describeValues(const ParsedCommand& c) {
  std::ostringstream o;
  const char* sep = "";
  for (const std::string& p : c.palettes) {
    o << sep << "palette " << p;
    sep = ", ";
  }
  const CueValues& v = c.values;
  if (v.intensity) o << sep << "intensity " << percent(*v.intensity) << " %", sep = ", ";
  if (v.panDeg) o << sep << "pan " << *v.panDeg, sep = ", ";
  if (v.tiltDeg) o << sep << "tilt " << *v.tiltDeg, sep = ", ";
  if (v.zoomDeg) o << sep << "zoom " << *v.zoomDeg, sep = ", ";
  if (v.iris) o << sep << "iris " << percent(*v.iris) << " %", sep = ", ";
  if (v.frost) o << sep << "frost " << percent(*v.frost) << " %", sep = ", ";
  if (v.gateFocus) o << sep << "focus " << percent(*v.gateFocus) << " %", sep = ", ";
  if (v.color) o << sep << "colour [" << v.color->r << ", " << v.color->g << ", " << v.color->b << "]", sep = ", ";
  if (c.colorSlot) o << sep << "colour " << *c.colorSlot, sep = ", ";
  if (v.ctoMired) o << sep << "cto " << *v.ctoMired << " mired", sep = ", ";
  if (c.goboSlot) o << sep << "gobo " << *c.goboSlot, sep = ", ";
  if (v.goboRotationDeg) o << sep << "gobo rotation " << *v.goboRotationDeg, sep = ", ";
  if (v.goboSpinDegS) o << sep << "gobo spin " << *v.goboSpinDegS << " degrees/s", sep = ", ";
  if (c.prismSlot) o << sep << "prism " << *c.prismSlot, sep = ", ";
  if (v.prismRotationDeg) o << sep << "prism rotation " << *v.prismRotationDeg, sep = ", ";
  if (v.prismSpinDegS) o << sep << "prism spin " << *v.prismSpinDegS << " degrees/s", sep = ", ";
  if (v.shutter)
    o << sep << (v.shutter->strobing() ? "strobe " + std::to_string(v.shutter->rateHz).substr(0, 5) + " Hz"
                                       : std::string("shutter ") + shutterModeName(v.shutter->mode)),
        sep = ", ";
  return o.str();
}

std::string lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

// A slot of `slots` (names) as typed: its name in any case, or its number from 1; "open" is the
// open slot whatever the wheel calls it first. -1: none.
int slotIndex(const std::vector<std::string>& slots, const std::string& typed) {
  for (size_t k = 0; k < slots.size(); ++k)
    if (lower(slots[k]) == lower(typed)) return static_cast<int>(k);
  if (!typed.empty() && std::all_of(typed.begin(), typed.end(), [](char ch) { return ch >= '0' && ch <= '9'; }) &&
      typed.size() < 6) {
    const int n = std::stoi(typed);
    if (n >= 1 && static_cast<size_t>(n) <= slots.size()) return n - 1;
  }
  return -1;
}

std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (size_t k = 0; k < names.size(); ++k) out += (k ? ", " : "") + std::to_string(k + 1) + " " + names[k];
  return out.empty() ? "none" : out;
}

// The colour wheel slot, gobo and prism the line names, for one fixture from its profile.
Status resolveSlots(const ShowDocument& doc, const ParsedCommand& c, int id, CueValues& v) {
  if (!c.colorSlot && !c.goboSlot && !c.prismSlot) return Ok{};
  const FixtureDef* f = doc.show().findFixture(id);
  auto it = f ? doc.profiles().find(f->profile) : doc.profiles().end();
  if (it == doc.profiles().end() || !it->second)
    return Error{"", "fixture " + std::to_string(id), "its profile is not loaded; nothing was changed"};
  const Profile& p = *it->second;
  const std::string who = "fixture " + std::to_string(id) + " (" + (p.name.empty() ? f->profile : p.name) + ")";
  if (c.colorSlot) {
    std::vector<std::string> names;
    if (!p.colorWheels.empty())
      for (const WheelSlot& s : p.colorWheels.front().slots) names.push_back(s.name);
    const int k = slotIndex(names, *c.colorSlot);
    if (k < 0)
      return Error{"", "color " + *c.colorSlot,
                   who + " has no colour wheel slot " + *c.colorSlot + " (its slots: " + listed(names) +
                       ") and it names no colour palette or colour; nothing was changed"};
    const WheelSlot& slot = p.colorWheels.front().slots[static_cast<size_t>(k)];
    v.color = slot.color ? *slot.color : glm::vec3(1.0f);
  }
  if (c.goboSlot) {
    std::vector<std::string> names;
    if (!p.goboWheels.empty())
      for (const WheelSlot& s : p.goboWheels.front().slots) names.push_back(s.name);
    const int k = lower(*c.goboSlot) == "open" && slotIndex(names, "open") < 0 ? -2 : slotIndex(names, *c.goboSlot);
    if (k == -1)
      return Error{"", "gobo " + *c.goboSlot, who + " has no gobo " + *c.goboSlot + " (its gobos: " + listed(names) +
                                                  "); nothing was changed"};
    v.gobo = k == -2 ? std::string("Open") : names[static_cast<size_t>(k)];
  }
  if (c.prismSlot) {
    std::vector<std::string> names;
    for (const PrismSpec& s : p.prisms) names.push_back(s.name);
    const int k = lower(*c.prismSlot) == "open" ? -2 : slotIndex(names, *c.prismSlot);
    if (k == -1)
      return Error{"", "prism " + *c.prismSlot, who + " has no prism " + *c.prismSlot + " (its prisms: " +
                                                    listed(names) + "); nothing was changed"};
    v.prism = k == -2 ? std::string("Open") : names[static_cast<size_t>(k)];
  }
  return Ok{};
}

std::string fixtures(const std::vector<int>& ids) {
  return std::to_string(ids.size()) + (ids.size() == 1 ? " fixture (" : " fixtures (") + describeIds(ids) + ")";
}

Result<std::string> setValues(ShowDocument& doc, const std::string& line, const ParsedCommand& c) {
  const std::vector<int> ids = c.selection ? *c.selection : doc.selection;
  if (ids.empty())
    return Error{"", "selection", "no fixture is selected; name them first, as in \"1 thru 4 @ 50\""};
  const Show& show = doc.show();
  std::map<int, CueValues> values;
  for (int id : ids) {
    CueValues v;
    for (const std::string& name : c.palettes) {
      const PaletteDef* p = show.findPalette(name);
      const auto given = p ? paletteValuesFor(show, *p, id) : std::nullopt;
      if (!given)
        return Error{"", "palette " + name, "the palette has no value for fixture " + std::to_string(id) +
                                                "; nothing was changed"};
      // A reference, not a copy: a cue recorded from the programmer follows the palette.
      applyPalette(show, v, id, *p);
    }
    layValues(v, c.values);
    if (Status s = resolveSlots(doc, c, id, v); !s) return s.error();
    values[id] = v;
  }
  Status s = doc.run(std::make_unique<CommandLineEdit>(line, setProgrammer(std::move(values))));
  if (!s) return s.error();
  doc.selection = ids;
  return "Set " + fixtures(ids) + ": " + describeValues(c);
}

std::string listWord(const ShowDocument& doc, size_t list) {
  return doc.show().cueLists.size() > 1 ? " of cue list \"" + doc.show().cueLists[list].name + "\"" : "";
}

Result<std::string> recordOrUpdate(ShowDocument& doc, const std::string& line, const ParsedCommand& c) {
  const auto& lists = doc.show().cueLists;
  const CueList* list = c.cueList < lists.size() ? &lists[c.cueList] : nullptr;
  const std::string listName = list ? list->name : "";
  const std::string ref = (c.cueList > 0 ? std::to_string(c.cueList + 1) + "/" : "") + c.cueNumber;
  const std::string in = listWord(doc, c.cueList);
  const bool exists = list && findCue(*list, c.cueNumber).ok();
  const bool empty = doc.programmer().values.empty();
  if (c.action == ParsedCommand::Action::Update) {
    if (!exists) return Error{"", "cue " + ref, "there is no cue " + c.cueNumber + in + " to update; 'record cue " + ref + "' makes it"};
    if (empty) return Error{"", "cue " + ref, "the programmer is empty: there is nothing to update the cue with"};
    Status s = doc.run(std::make_unique<CommandLineEdit>(line, updateCue(listName, c.cueNumber)));
    if (!s) return s.error();
    return "Updated cue " + c.cueNumber + in;
  }
  if (exists) return Error{"", "cue " + ref, "cue " + c.cueNumber + in + " exists; 'update cue " + ref + "' changes it"};
  CueRecord r;
  r.list = listName;
  r.number = c.cueNumber;
  if (list)
    for (const Cue& q : list->cues)
      if (compareCueNumbers(q.number, c.cueNumber) < 0) r.after = q.number;
  Status s = doc.run(std::make_unique<CommandLineEdit>(line, recordCue(std::move(r))));
  if (!s) return s.error();
  return "Recorded cue " + c.cueNumber + in + (empty ? " (the programmer was empty: the cue changes nothing)" : "");
}

Result<std::string> groupOrPalette(ShowDocument& doc, const std::string& line, const ParsedCommand& c) {
  using A = ParsedCommand::Action;
  const Show& show = doc.show();
  std::unique_ptr<EditCommand> edit;
  std::string done;
  switch (c.action) {
    case A::RecordPalette: {
      const PaletteKind kind = c.paletteKind ? *c.paletteKind : paletteKindOfProgrammer(show, doc.programmer());
      edit = recordPalette(c.name, c.paletteKind);
      done = std::string("Recorded ") + paletteKindName(kind) + " palette \"" + c.name + "\"";
      bool intensity = false;
      for (const auto& [id, v] : doc.programmer().values) intensity = intensity || resolveValues(show, id, v).intensity;
      if (intensity && kind != PaletteKind::All)
        done += std::string(" (intensity left out: a ") + paletteKindName(kind) + " palette holds " +
                paletteKindAttributes(kind) + ")";
      break;
    }
    case A::UpdatePalette:
      edit = updatePalette(c.name);
      done = "Updated palette \"" + c.name + "\"";
      break;
    case A::DeletePalette:
      edit = deletePalette(c.name);
      done = "Deleted palette \"" + c.name + "\"";
      break;
    case A::RecordGroup:
      edit = recordGroup(c.name, doc.selection);
      done = "Recorded group \"" + c.name + "\" of " + fixtures(doc.selection);
      break;
    default:
      edit = deleteGroup(c.name);
      done = "Deleted group \"" + c.name + "\"";
      break;
  }
  Status s = doc.run(std::make_unique<CommandLineEdit>(line, std::move(edit)));
  if (!s) return s.error();
  return done;
}

std::string seconds(double s) {
  std::ostringstream o;
  o << s << " s";
  return o.str();
}

// cue N time T delay D follow F, label cue N TEXT: one edit of an existing cue.
Result<std::string> cueTimesOrLabel(ShowDocument& doc, const std::string& line, const ParsedCommand& c) {
  const auto& lists = doc.show().cueLists;
  const CueList* list = c.cueList < lists.size() ? &lists[c.cueList] : nullptr;
  const std::string ref = (c.cueList > 0 ? std::to_string(c.cueList + 1) + "/" : "") + c.cueNumber;
  auto at = list ? findCue(*list, c.cueNumber) : Result<size_t>(Error{"", "", "the show has no cues"});
  if (!at) return Error{"", "cue " + ref, at.error().message};
  const Cue& cue = list->cues[*at];
  const std::string in = listWord(doc, c.cueList);
  if (c.action == ParsedCommand::Action::LabelCue) {
    Status s = doc.run(std::make_unique<CommandLineEdit>(line, labelCue(list->name, cue.number, c.name)));
    if (!s) return s.error();
    return "Cue " + cue.number + in + (c.name.empty() ? " has no label" : " is labelled \"" + c.name + "\"");
  }
  CueTimes t{.fadeS = c.fadeS.value_or(cue.fadeS), .delayS = c.delayS.value_or(cue.delayS),
             .followS = c.followS.value_or(cue.followS)};
  Status s = doc.run(std::make_unique<CommandLineEdit>(line, setCueTimes(list->name, cue.number, t)));
  if (!s) return s.error();
  return "Cue " + cue.number + in + ": fade " + seconds(t.fadeS) + ", delay " + seconds(t.delayS) + ", follow " +
         (t.followS ? seconds(*t.followS) : std::string("off"));
}

std::string cueName(const CueList& list, size_t index) {
  const Cue& q = list.cues[index];
  return "cue " + q.number + (q.label.empty() ? "" : " (" + q.label + ")");
}

}  // namespace

std::string describeIds(const std::vector<int>& ids) { return idRanges(ids); }

Result<std::string> runCommandLine(ShowDocument& doc, const std::string& typed, double nowS) {
  const std::string line = trimmed(typed);
  auto parsed = parseCommand(line, doc.show());
  if (!parsed) return parsed.error();
  const ParsedCommand& c = *parsed;
  switch (c.action) {
    case ParsedCommand::Action::None:
      if (!c.selection) return std::string();
      doc.selection = *c.selection;
      return "Selected " + fixtures(*c.selection);
    case ParsedCommand::Action::Set:
      return setValues(doc, line, c);
    case ParsedCommand::Action::Record:
    case ParsedCommand::Action::Update:
      return recordOrUpdate(doc, line, c);
    case ParsedCommand::Action::GotoCue: {
      const auto& lists = doc.show().cueLists;
      const CueList* list = c.cueList < lists.size() ? &lists[c.cueList] : nullptr;
      const std::string ref = (c.cueList > 0 ? std::to_string(c.cueList + 1) + "/" : "") + c.cueNumber;
      auto at = list ? findCue(*list, c.cueNumber) : Result<size_t>(Error{"", "", "the show has no cues"});
      if (!at) return Error{"", "cue " + ref, at.error().message};
      if (!doc.listGotoCue(c.cueList, *at, nowS)) return Error{"", "cue " + ref, "playback could not go to the cue"};
      return "Going to " + cueName(*list, *at) + listWord(doc, c.cueList);
    }
    case ParsedCommand::Action::RecordPalette:
    case ParsedCommand::Action::UpdatePalette:
    case ParsedCommand::Action::DeletePalette:
    case ParsedCommand::Action::RecordGroup:
    case ParsedCommand::Action::DeleteGroup:
      return groupOrPalette(doc, line, c);
    case ParsedCommand::Action::CueTimes:
    case ParsedCommand::Action::LabelCue:
      return cueTimesOrLabel(doc, line, c);
    case ParsedCommand::Action::DefaultFade: {
      Status s = doc.run(std::make_unique<CommandLineEdit>(line, setDefaultFade(*c.fadeS)));
      if (!s) return s.error();
      return "Cues recorded from now on fade in " + seconds(*c.fadeS);
    }
    case ParsedCommand::Action::ChangeType: {
      const std::vector<int> ids = c.selection ? *c.selection : doc.selection;
      if (ids.empty()) return Error{"", "type", "no fixtures selected; expected a selection before 'type' (11 thru 20 type ...)"};
      std::string title;
      auto file = resolveFixtureType(c.name, {}, &title);
      if (!file) return Error{"", "type", file.error().message};
      auto report = doc.changeFixtureType(ids, *file, c.mode);
      if (!report) return report.error();
      doc.selection = ids;
      const FixtureDef* f = doc.show().findFixture(ids.front());
      std::string said = "Changed " + fixtures(ids) + " to " + title + ", mode \"" + (f ? f->mode : c.mode) + "\"";
      if (!report->lines.empty())
        said += "; " + std::to_string(report->lines.size()) + " values not carried over as they were (" + report->lines.front() +
                (report->lines.size() > 1 ? "; ..." : "") + ")";
      return said;
    }
    case ParsedCommand::Action::Go: {
      if (!doc.go(nowS)) return Error{"", "go", "there is no next cue"};
      const auto now = doc.currentCue();
      return "GO: " + (now && doc.cueList() ? cueName(*doc.cueList(), *now) : std::string("next cue"));
    }
    case ParsedCommand::Action::Clear: {
      const size_t held = doc.programmer().values.size();
      if (held > 0) {
        Status s = doc.run(std::make_unique<CommandLineEdit>(line, clearProgrammer()));
        if (!s) return s.error();
      }
      doc.selection.clear();
      return "Cleared the selection and the programmer (" + std::to_string(held) + " fixtures)";
    }
  }
  return std::string();
}

}  // namespace haze
