// ShowDocument: one open show as the GUI edits it, without any window: the show, its profiles,
// venue and BVH (for picking), the programmer, the undo history, the fixture selection and the
// cue player. Every action of the GUI's panels that changes the show is a method here that runs
// a command through the history, so the whole designer's path (place, aim, focus, record, save,
// reopen) is tested without a window (tests/unit/app/show_document_test.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "shows/edit/picking.h"
#include "shows/scene/bvh.h"
#include "shows/scene/venue.h"
#include "shows/playbacks.h"
#include "shows/edit/edit_change_type.h"
#include "shows/edit/edit_commands.h"
#include "shows/edit/edit_history.h"
#include "shows/focus.h"
#include "shows/show.h"

namespace haze {

// Fixture ids whose DMX footprint overlaps another patched fixture's in the same universe, or
// runs outside 1..512 (the patch table shows them in red).
std::set<int> patchConflicts(const Show& show, const ProfileSet& profiles);

class ShowDocument {
 public:
  // Loads a show with its profiles and venue.
  static Result<std::unique_ptr<ShowDocument>> open(const std::filesystem::path& file);
  // A new, unsaved show on the same venue as `like` (its cameras and atmosphere too), with no
  // fixtures, profiles or cues; `like` may be null for an empty stage.
  static Result<std::unique_ptr<ShowDocument>> blank(const ShowDocument* like);

  ShowDocument(const ShowDocument&) = delete;
  ShowDocument& operator=(const ShowDocument&) = delete;

  const Show& show() const { return show_; }
  const ProfileSet& profiles() const { return profiles_; }
  const Venue& venue() const { return venue_; }
  const Bvh& bvh() const { return *bvh_; }
  const Programmer& programmer() const { return programmer_; }
  const EditHistory& history() const { return history_; }
  // Changes on every edit, undo and redo: the view redraws and refines again when it moves.
  std::uint64_t revision() const { return revision_; }
  bool untitled() const { return show_.file.empty(); }
  // Unsaved changes: edits (adding a profile is one) since the last save.
  bool modified() const { return history_.modified(); }
  std::string title() const;  // "haze - demo.haze.json *"

  // --- Edits (each one undo step; merge = part of a drag that continues the newest step). ---
  Status run(std::unique_ptr<EditCommand> command, bool merge = false);
  bool undo();
  bool redo();

  // Adds a profile file (native .json, .ies, .ldt, .gdtf) to the show's library under a key made
  // from its file name; returns the key. The file is referred to relative to the show. One undo
  // step (Add profile KEY).
  Result<std::string> addProfileFile(const std::filesystem::path& file);
  // Change fixture type (shows/edit/edit_change_type.h): the fixtures get the profile in `file`
  // (any profile file; a library file outside the show's folder is referred to by its absolute
  // path) in `mode` ("" = its first). One undo step; the report says what was not carried over.
  Result<ChangeTypeReport> changeFixtureType(const std::vector<int>& ids, const std::filesystem::path& file,
                                             const std::string& mode);
  // Places a fixture of `profileKey` at a mounting pose and selects it; returns its id.
  Result<int> placeFixtureAt(const std::string& profileKey, const MountPose& pose);
  // Focus to point: every selected fixture's pan and tilt so its beam axis goes through the
  // point (or its nearest reachable direction), as one programmer step. Returns the results in
  // selection order. merge: a step of a drag (aiming by the beam's end) that continues the last.
  Result<std::vector<FocusResult>> focusSelectionOn(const glm::vec3& pointM, const StageState& onStage,
                                                    bool merge = false);
  // Sets attributes of every selected fixture in the programmer.
  Status setSelectionValues(const CueValues& values, bool merge);
  // Records the programmer into a new cue of the first list after cue `afterNumber` ("" = at the
  // end) and returns its number.
  Result<std::string> recordCue(const std::string& afterNumber = "", const std::string& label = "");
  // The same at the end of cue list `list` (an index into show().cueLists).
  Result<std::string> recordCueInList(size_t list, const std::string& label = "");
  // The same from a look (fixture id -> values, e.g. what DMX put on stage) instead of the
  // programmer: a new cue at the end of the list, one undo step.
  Result<std::string> recordLook(std::map<int, CueValues> look, const std::string& label = "");

  // Saves to `file` ("" = where it was loaded from) through the shows library's safe save.
  Status save(const std::filesystem::path& file = {}, bool force = false);

  // --- Selection (fixture ids, sorted). ---
  std::vector<int> selection;

  // --- Playback: every cue list at once (shows/playbacks.h), each with GO, BACK and a master;
  // the methods without a list act on the first list, which Record and the cue tab edit. An edit
  // of the cues rebuilds the players on the same cues, in full (masters kept); other edits
  // (fixtures, programmer) leave a running fade alone. ---
  // The first cue list, or null when the show has none.
  const CueList* cueList() const;
  bool go(double nowS) { return listGo(0, nowS); }
  bool back(double nowS) { return listBack(0, nowS); }
  bool gotoCue(size_t index, double nowS);
  bool jumpTo(size_t index, double nowS);
  std::optional<size_t> currentCue() const { return listCue(0); }
  // 0..1 of the first list's current fade (-1 in its delay, 1 when done or when no cue is active).
  double fadeProgress(double nowS) const { return listFadeProgress(0, nowS); }
  bool fading(double nowS) const;

  // Cue list `list` (an index into show().cueLists); false when there is no such cue or list.
  size_t listCount() const { return show_.cueLists.size(); }
  bool listGo(size_t list, double nowS);
  bool listBack(size_t list, double nowS);
  bool listGotoCue(size_t list, size_t index, double nowS);
  std::optional<size_t> listCue(size_t list) const;
  double listFadeProgress(size_t list, double nowS) const;
  void setListMaster(size_t list, double level);
  double listMaster(size_t list) const;
  // The stage now: playback with the programmer laid over it (what is rendered).
  StageState stageState(double nowS);

 private:
  ShowDocument() = default;
  EditTarget target() { return EditTarget{show_, programmer_, profiles_}; }
  void changed();
  void resetPlayer();

  Show show_;
  ProfileSet profiles_;
  Venue venue_;
  std::unique_ptr<Bvh> bvh_;
  Programmer programmer_;
  EditHistory history_;
  // Every profile read in this session by key, so that undo and redo of adding one only need to
  // keep profiles_ to the keys of show_.profiles (changed()).
  ProfileSet loaded_;
  std::uint64_t revision_ = 1;

  std::unique_ptr<Playbacks> playbacks_;
  std::vector<CueList> playerCues_;  // the cue lists the players were built on
  std::vector<PaletteDef> playerPalettes_;  // and the palettes and groups they resolve
  std::vector<GroupDef> playerGroups_;
  double lastNowS_ = 0.0;
};

}  // namespace haze
