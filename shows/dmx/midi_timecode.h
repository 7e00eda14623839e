// MIDI Time Code (MMA "MIDI Time Code" spec, RP-004/008): a byte stream of MIDI messages in, SMPTE
// readings out, for `haze live --mtc` (docs/live.md, "Timecode"). Two kinds of message carry it:
//   Quarter Frame F1 0n: n = piece << 4 | nibble. Pieces 0..7 are frames low/high nibble, seconds
//     low/high, minutes low/high, hours low, and hours high with the rate (bits 1-2: 0 = 24,
//     1 = 25, 2 = 29.97 drop-frame, 3 = 30 fps). A tape running forward sends 0..7, four a frame;
//     the time they spell is that of the frame piece 0 went out on, two frames old when piece 7
//     arrives, so the reading is that time plus two frames. Running backwards they come 7..0 and
//     the reading (at piece 0) is the time as spelt, minus two frames.
//   Full Frame F0 7F cc 01 01 hr mn sc fr F7 (hr = rate << 5 | hours; cc the device, 7F = all):
//     sent on a locate or when the tape stops: the time at once.
// Anything else in the stream (other messages, running status, real-time bytes) is skipped.
// A cycle broken by a missing or out-of-order piece is dropped (counted) and assembly restarts.
// Pure bytes in: no devices; never throws.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "shows/timecode.h"

namespace haze {

struct MtcReading {
  Timecode time;
  int rateCode = 1;        // 0 = 24, 1 = 25, 2 = 29.97 drop-frame, 3 = 30
  bool fullFrame = false;  // from a Full Frame message (a locate), not quarter frames
  double fps() const;      // 24, 25, 29.97 or 30
};

struct MtcStats {
  uint64_t quarterFrames = 0;
  uint64_t fullFrames = 0;
  uint64_t brokenCycles = 0;  // quarter-frame cycles dropped: a piece missing or out of order
  uint64_t badTimes = 0;      // a time out of range (hours > 23, frames >= the rate...)
};

class MtcDecoder {
 public:
  // Feeds bytes (any split: a message may straddle calls); returns the readings they completed.
  std::vector<MtcReading> feed(std::span<const uint8_t> bytes);
  const MtcStats& stats() const { return stats_; }

 private:
  void quarterFrame(uint8_t data, std::vector<MtcReading>& out);
  void sysex(std::vector<MtcReading>& out);
  std::optional<MtcReading> assemble(int direction);

  MtcStats stats_;
  int status_ = 0;            // the message being read: 0xF1, 0xF0, or 0 (skipping)
  std::vector<uint8_t> sysex_;
  uint8_t pieces_[8] = {};
  int havePieces_ = 0;        // bit mask of the pieces of the current cycle
  int lastPiece_ = -1;
  int direction_ = 0;         // +1 forward, -1 backward, 0 not known yet
};

// The frame after (or before) `t` at the rate, drop-frame numbering for rate code 2 (frames 0
// and 1 are skipped at the start of each minute but every tenth). Empty past the day's ends.
std::optional<Timecode> stepFrame(const Timecode& t, int rateCode, int direction);

}  // namespace haze
