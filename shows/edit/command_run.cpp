// runCommandLine: resolves everything a parsed line needs (the fixtures, the palettes' values for
// each of them, where a recorded cue goes) before it runs one edit, so that a line that cannot be
// done fails before anything changed.
#include "shows/edit/command_run.h"

#include <cmath>
#include <sstream>

#include "fixtures/fixture_library.h"
#include "shows/cue_number.h"
#include "shows/edit/command_syntax.h"
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
  return o.str();
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

std::string cueName(const CueList& list, size_t index) {
  const Cue& q = list.cues[index];
  return "cue " + q.number + (q.label.empty() ? "" : " (" + q.label + ")");
}

}  // namespace

std::string describeIds(const std::vector<int>& ids) {
  std::string s;
  for (size_t k = 0; k < ids.size();) {
    size_t run = k;
    while (run + 1 < ids.size() && ids[run + 1] == ids[run] + 1) ++run;
    s += (s.empty() ? "" : ", ") + std::to_string(ids[k]);
    if (run > k) s += "-" + std::to_string(ids[run]);
    k = run + 1;
  }
  return s;
}

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
