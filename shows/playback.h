// Cue playback, the tracking model of docs/show-format.md. The pure face: the state of every fixture
// at a moment after GO. The clock-driven player for the GUI and live playback (GO, BACK, GOTO,
// follow chains) is shows/cue_player.h and is built from the same pieces.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "fixtures/attributes.h"
#include "fixtures/core/result.h"
#include "shows/show.h"

namespace haze {

using StageState = std::map<int, Attributes>;  // fixture id -> attributes

// The tracked full state of cue cueIndex (all fixtures of the show, defaults where unset).
StageState trackedState(const Show& show, const ProfileSet& profiles, const CueList& list,
                        size_t cueIndex);
// The state secondsSinceGo after GO into cue cueIndex from the full state of the cue before it
// (before the first cue: every fixture at its defaults). Follows do not fire here; see
// CuePlayer for that.
StageState stateAt(const Show& show, const ProfileSet& profiles, const CueList& list,
                   size_t cueIndex, double secondsSinceGo);
// Index of the cue with this number ("1", "1.5"; "1.50" finds "1.5"), or an error naming the list.
Result<size_t> findCue(const CueList& list, const std::string& number);
// Every attribute of a fixture's state as cue values (recording a look seen on stage).
CueValues cueValuesOf(const Attributes& a);

// --- The pieces both faces share. ---

// Every fixture of the show at its defaults: the state before the first cue.
StageState defaultState(const Show& show);
// Lays one fixture's set values over its attributes: tracking, and the programmer over playback.
void overlayValues(Attributes& a, const CueValues& v);

struct CueTiming {
  double delayS = 0.0;
  double fadeS = 0.0;
};

// Where a crossfade is secondsSinceGo after GO: -1 during the delay (nothing has moved), then
// 0..1 linearly over the fade, 1 when done; a fade of 0 jumps from -1 to 1 when the delay ends.
double fadeProgress(const CueTiming& timing, double secondsSinceGo);

// One fixture's attributes at `progress` (from fadeProgress): continuous attributes linear from
// `from` to `to`, colour per channel, gobo, prism and shutter switched as soon as progress >= 0. An unset zoom
// stands for fieldAngleDeg (the profile's field angle) while fading to or from a set one.
Attributes blendAttributes(const Attributes& from, const Attributes& to, double progress,
                           std::optional<float> fieldAngleDeg);
// The same for a whole stage; fixtures are matched by id, field angles come from `profiles`.
StageState blendStates(const Show& show, const ProfileSet& profiles, const StageState& from,
                       const StageState& to, double progress);

// --- A cue's own timing (docs/show-format.md, "Timing"). ---

// The times one fixture's parts follow in a cue: intensity up and down, position (pan, tilt),
// colour (colour and cell colours) and beam (everything else), each the cue's delay and fade
// unless the cue's timing sets its own, plus the fixture's place in the cue's fan.
struct FixtureTiming {
  CueTiming up, down, position, color, beam;
  FadeCurve curve = FadeCurve::Linear;
  double endS() const;  // when its last part has finished
};
FixtureTiming fixtureTiming(const Show& show, const Cue& cue, int fixtureId);
// When the last part of the last fixture has finished: the cue's "delay + fade" for follows.
double cueDurationS(const Show& show, const Cue& cue);
// A fade curve applied to a linear progress in 0..1 (values outside pass through): linear is p,
// s-curve is 3p^2 - 2p^3.
double curveProgress(FadeCurve curve, double linearProgress);
// One fixture secondsSinceGo into a cue with these times, each part on its own clock and curve.
Attributes blendAttributesAt(const Attributes& from, const Attributes& to, const FixtureTiming& timing,
                             double secondsSinceGo, std::optional<float> fieldAngleDeg);
// The same for a whole stage, each fixture with its own timing in `cue`.
StageState blendStatesAt(const Show& show, const ProfileSet& profiles, const StageState& from,
                         const StageState& to, const Cue& cue, double secondsSinceGo);

}  // namespace haze
