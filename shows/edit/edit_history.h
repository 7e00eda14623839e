// The GUI's editing core without a window: the programmer (live values that override playback,
// what a designer records cues from), the command interface every show edit goes through, and the
// undo/redo history. Commands themselves are in shows/edit/edit_commands.h.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fixtures/core/result.h"
#include "shows/playback.h"
#include "shows/show.h"

namespace haze {

// Like a console's programmer: per fixture, the attributes the designer has set by hand and the
// palettes applied (CueValues::palettes: references, resolved for the stage, so a palette
// updated while it is in the programmer shows at once). They win over cue playback on stage, and
// Record/Update take them into cues, references as references.
struct Programmer {
  std::map<int, CueValues> values;  // by fixture id; unset attributes leave playback alone
  bool operator==(const Programmer&) const = default;
};

// What the stage shows: the playback state with the programmer laid over it (its palette
// references resolved against `show`).
StageState withProgrammer(StageState state, const Programmer& programmer, const Show& show);

// Everything a command may read or change. The profiles are read-only: commands need them for
// DMX footprints, modes and tracked states.
struct EditTarget {
  Show& show;
  Programmer& programmer;
  const ProfileSet& profiles;
};

class EditCommand {
 public:
  virtual ~EditCommand() = default;
  // For the Edit menu: "Move fixture 3", "Record cue 1.5".
  virtual std::string label() const = 0;
  // Checks everything first; on an error nothing has changed. Applying again after undo gives
  // the same result (the history uses it for redo), so apply keeps what undo needs.
  virtual Status apply(EditTarget& target) = 0;
  // Restores exactly the state apply started from. Only called right after apply/redo.
  virtual void undo(EditTarget& target) = 0;
  // Takes over `next` (already applied, same kind, same things): a drag's hundred moves become one
  // undo step. False when it cannot.
  virtual bool absorb(const EditCommand& /*next*/) { return false; }
};

class EditHistory {
 public:
  explicit EditHistory(size_t maxSteps = 1000) : maxSteps_(maxSteps < 1 ? 1 : maxSteps) {}

  // Applies the command; on success it becomes the newest undo step (or is folded into it when
  // `merge` and the newest step absorbs it) and the redo steps are dropped. On an error the show is
  // unchanged and the history too.
  Status run(EditTarget& target, std::unique_ptr<EditCommand> command, bool merge = false);
  bool undo(EditTarget& target);  // false when there is nothing to undo
  bool redo(EditTarget& target);  // false when there is nothing to redo
  bool canUndo() const { return !done_.empty(); }
  bool canRedo() const { return !undone_.empty(); }
  std::string undoLabel() const { return done_.empty() ? "" : done_.back().command->label(); }
  std::string redoLabel() const { return undone_.empty() ? "" : undone_.back().command->label(); }
  size_t undoSteps() const { return done_.size(); }
  // Forgets every step; the current state counts as the saved one (after loading a show).
  void clear();

  // Unsaved-changes tracking: markSaved after a save; modified() is true when undo/redo/run have
  // moved the show away from the saved state.
  void markSaved() { savedSerial_ = topSerial(); }
  bool modified() const { return topSerial() != savedSerial_; }

 private:
  struct Step {
    std::unique_ptr<EditCommand> command;
    std::uint64_t serial = 0;
  };
  std::uint64_t topSerial() const { return done_.empty() ? 0 : done_.back().serial; }

  size_t maxSteps_;
  std::vector<Step> done_;    // oldest first
  std::vector<Step> undone_;  // the next redo last
  std::uint64_t nextSerial_ = 1;
  std::uint64_t savedSerial_ = 0;  // 0 = the state before any step; ~0 = a state no longer reachable
};

}  // namespace haze
