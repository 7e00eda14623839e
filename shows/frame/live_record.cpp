// Recording through the edit commands the GUI uses, so a cue recorded from a console is the
// same as one recorded by hand.
#include "shows/frame/live_record.h"

#include <algorithm>

#include "shows/cue_number.h"
#include "shows/edit/edit_commands.h"
#include "shows/show_save.h"

namespace haze {


Result<std::string> recordLiveCue(Show& show, const ProfileSet& profiles, const StageState& stage,
                                  const std::set<int>& fixtures, const LiveRecord& r) {
  if (!isCueNumber(r.number))
    return Error{"", "--record-cue", "'" + r.number + "' is not a cue number; expected one like 10 or 1.5"};
  if (show.file.empty()) return Error{"", "--record-cue", "the show has no file to save to"};
  Programmer programmer;
  for (int id : fixtures)
    if (auto it = stage.find(id); it != stage.end()) programmer.values[id] = cueValuesOf(it->second);
  const CueList* list = nullptr;
  for (const CueList& l : show.cueLists)
    if (r.list.empty() ? true : l.name == r.list) {
      list = &l;
      break;
    }
  if (!r.list.empty() && !list)
    return Error{"", "--cue-list", "the show has no cue list \"" + r.list + "\""};
  const std::string listName = list ? list->name : "";
  EditTarget target{show, programmer, profiles};
  bool exists = false;
  std::string after;  // the last cue before the new number
  if (list)
    for (const Cue& c : list->cues) {
      const int order = compareCueNumbers(c.number, r.number);
      if (order == 0) exists = true;
      if (order < 0) after = c.number;
    }
  Status applied = exists ? updateCue(listName, r.number)->apply(target)
                          : recordCue(CueRecord{listName, after, r.number, r.label})->apply(target);
  if (!applied) return applied.error();
  if (exists && !r.label.empty()) {
    if (Status s = labelCue(listName, r.number, r.label)->apply(target); !s) return s.error();
  }
  // The list the cue went into (recordCue makes "Main" when the show had none).
  const CueList& into = listName.empty() ? show.cueLists.front() : *std::find_if(show.cueLists.begin(), show.cueLists.end(),
                                                                                [&](const CueList& l) { return l.name == listName; });
  size_t values = 0;
  if (auto at = findCue(into, r.number))
    for (const auto& [id, v] : into.cues[*at].values)
      values += v.intensity.has_value() + v.panDeg.has_value() + v.tiltDeg.has_value() + v.color.has_value() +
                v.zoomDeg.has_value() + v.gobo.has_value() + v.goboRotationDeg.has_value() + v.iris.has_value() +
                v.frost.has_value() + v.gateFocus.has_value() + v.prism.has_value() + v.prismRotationDeg.has_value() + v.blades.has_value() +
                v.bladeRotationDeg.has_value() + v.shutter.has_value() + v.gobo2.has_value() +
                v.gobo2RotationDeg.has_value() + v.goboSpinDegS.has_value() + v.gobo2SpinDegS.has_value() +
                v.prismSpinDegS.has_value() + v.color2.has_value() + v.ctoMired.has_value() + v.animation.has_value() +
                v.animationRotationDeg.has_value() + v.animationSpinDegS.has_value() + v.cells.size();
  const std::filesystem::path file = show.file;
  if (Status s = saveShow(show, file); !s) return s.error();
  return std::string(exists ? "updated" : "recorded") + " cue " + r.number + " from " + std::to_string(fixtures.size()) +
         " fixtures (" + std::to_string(values) + " values that differ from tracking) and saved " + file.string();
}

}  // namespace haze
