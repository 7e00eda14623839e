// Playbacks: every cue list of a show played at once, each with its own CuePlayer (GO, BACK,
// GOTO, follows) and a master level, merged into one stage as consoles do (docs/shows.md,
// "Several cue lists at once"):
//   intensity   HTP: the highest of master x the list's intensity over the lists that have
//               played a cue (cell intensities: the highest over the lists that set that cell)
//   the rest    LTP: each attribute of each fixture comes from the list that asserted it last;
//               a GO asserts what the cue itself holds (its values and its effects' attributes),
//               BACK, GOTO and a jump assert everything the target cue's tracked state holds;
//               a list never lets go of an attribute it once asserted (going back before the
//               cue that set it, the list fades it to its default, as a single list does)
//   nobody      a fixture attribute no list holds stays at its default
// A list taking an attribute over fades it from what was on stage at that moment, with its own
// cue's timing. The master scales intensity only: a list at master 0 still holds its LTP
// attributes (consoles differ; this one lets a list at zero preset positions).
// Time is passed in, as for CuePlayer; follows of all lists fire in time order.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "shows/cue_player.h"

namespace haze {

// The attributes that merge LTP between lists, one at a time (a cell's colour is one per cell).
enum class LtpAttribute {
  Pan, Tilt, Color, Zoom, Gobo, GoboRotation, Iris, Frost, Prism, PrismRotation, Blades, BladeRotation,
  Shutter, Gobo2, Gobo2Rotation, GoboSpin, Gobo2Spin, PrismSpin, Color2, Cto, Animation, AnimationRotation, AnimationSpin, GateFocus, CellColor,
  CellIntensity,  // HTP, but only among the lists that set it (its default is 1, not 0)
};

// One held attribute: fixture id, attribute, cell index (CellColor, CellIntensity; else 0).
using HeldKey = std::tuple<int, LtpAttribute, int>;

// The attributes a cue's values for one fixture (palettes resolved) set.
std::vector<HeldKey> heldKeys(int fixtureId, const CueValues& values);

class Playbacks {
 public:
  // One playback per cue list of the show, in the show's order, each at master 1 and before its
  // first cue. The show and profiles must outlive this object, and the show's cue lists must not
  // change under it (rebuild it after an edit).
  Playbacks(const Show& show, const ProfileSet& profiles);
  Playbacks(const Playbacks&) = delete;
  Playbacks& operator=(const Playbacks&) = delete;

  size_t size() const { return slots_.size(); }
  const CueList& list(size_t i) const { return *slots_[i].list; }
  // The playback of the list with this name.
  std::optional<size_t> find(const std::string& name) const;

  // As CuePlayer's; each returns false (and changes nothing) when there is no such cue or list.
  bool go(size_t i, double nowS);
  bool back(size_t i, double nowS);
  bool gotoCue(size_t i, size_t cueIndex, double nowS);
  bool jumpTo(size_t i, size_t cueIndex, double nowS);
  // Takes list i off stage at once: before its first cue again, holding nothing, its master kept.
  void release(size_t i);

  // The master, clamped to 0..1; it acts at once (a fader).
  void setMaster(size_t i, double level);
  double master(size_t i) const { return slots_[i].master; }

  std::optional<size_t> currentCue(size_t i) const { return slots_[i].player->currentCue(); }
  bool fading(size_t i, double nowS) const { return slots_[i].player->fading(nowS); }
  // When list i last started a cue (GO, BACK, GOTO or a follow); none before its first.
  std::optional<double> lastStartS(size_t i) const { return slots_[i].lastStartS; }
  // The earliest follow armed in any list.
  std::optional<double> nextFollowAtS() const;
  // Which list holds an attribute now (none: no list does).
  std::optional<size_t> holder(const HeldKey& key) const;
  // The order in which the lists last asserted something, oldest first (lists never started
  // left out): replaying jumps in this order rebuilds the same holders.
  std::vector<size_t> startOrder() const;

  // Fires every list's follows due by nowS, in time order.
  void update(double nowS);
  // Fires the follows due by nowS, then returns the merged stage at nowS.
  StageState state(double nowS);

 private:
  struct Slot {
    const CueList* list = nullptr;
    std::unique_ptr<CuePlayer> player;
    double master = 1.0;
    std::map<HeldKey, uint64_t> held;  // what the list holds, with the order it asserted it in
    uint64_t lastAssert = 0;
    std::optional<double> lastStartS;
  };
  enum class Assert { Moves, Full };
  // The merged stage at nowS with every list's follows up to nowS already fired.
  StageState merged(double nowS);
  // After list i started cue `cue` at atS: stamp what it asserts and fade those attributes from
  // `before` (the merged stage just before the start).
  void asserted(size_t i, size_t cue, Assert how, double atS, const StageState* before);

  const Show& show_;
  const ProfileSet& profiles_;
  std::vector<Slot> slots_;
  uint64_t order_ = 0;
};

}  // namespace haze
