// MIDI Time Code decoding: quarter-frame assembly, full-frame sysex (see midi_timecode.h).
#include "shows/dmx/midi_timecode.h"

namespace haze {

namespace {
constexpr int kRateFrames[4] = {24, 25, 30, 30};
constexpr size_t kMaxSysex = 64;  // MTC's is 10 bytes; longer sysex is skipped, not stored

bool inRange(const Timecode& t, int rateCode) {
  if (t.hours > 23 || t.minutes > 59 || t.seconds > 59 || t.frames >= kRateFrames[rateCode]) return false;
  // Drop-frame: frames 0 and 1 do not exist at the start of a minute but every tenth.
  return !(rateCode == 2 && t.seconds == 0 && t.frames < 2 && t.minutes % 10 != 0);
}
}  // namespace

double MtcReading::fps() const {
  constexpr double kFps[4] = {24.0, 25.0, 30000.0 / 1001.0, 30.0};
  return kFps[rateCode & 3];
}

std::optional<Timecode> stepFrame(const Timecode& t, int rateCode, int direction) {
  const int n = kRateFrames[rateCode & 3];
  Timecode r = t;
  do {
    if (direction > 0) {
      if (++r.frames < n) continue;
      r.frames = 0;
      if (++r.seconds < 60) continue;
      r.seconds = 0;
      if (++r.minutes < 60) continue;
      r.minutes = 0;
      if (++r.hours < 24) continue;
      return std::nullopt;
    } else {
      if (--r.frames >= 0) continue;
      r.frames = n - 1;
      if (--r.seconds >= 0) continue;
      r.seconds = 59;
      if (--r.minutes >= 0) continue;
      r.minutes = 59;
      if (--r.hours >= 0) continue;
      return std::nullopt;
    }
  } while (false);
  // Skip the labels drop-frame leaves out (forward: to frame 2; backward: to the previous minute's 29).
  if ((rateCode & 3) == 2 && !inRange(r, 2)) return stepFrame(r, rateCode, direction);
  return r;
}

std::vector<MtcReading> MtcDecoder::feed(std::span<const uint8_t> bytes) {
  std::vector<MtcReading> out;
  for (const uint8_t b : bytes) {
    if (b >= 0xF8) continue;  // real-time bytes may come anywhere, even inside a sysex
    if (b & 0x80) {
      if (status_ == 0xF0 && b == 0xF7) sysex(out);
      status_ = (b == 0xF1 || b == 0xF0) ? b : 0;
      sysex_.clear();
      continue;
    }
    if (status_ == 0xF1) {
      quarterFrame(b, out);
      status_ = 0;  // one data byte; no running status for system common messages
    } else if (status_ == 0xF0) {
      if (sysex_.size() < kMaxSysex) sysex_.push_back(b);
      else status_ = 0;
    }
  }
  return out;
}

void MtcDecoder::sysex(std::vector<MtcReading>& out) {
  // 7F cc 01 01 hr mn sc fr: universal real time, MTC, full message.
  const auto& s = sysex_;
  if (s.size() != 8 || s[0] != 0x7F || s[2] != 0x01 || s[3] != 0x01) return;
  ++stats_.fullFrames;
  MtcReading r;
  r.rateCode = (s[4] >> 5) & 3;
  r.time = Timecode{s[4] & 0x1F, s[5], s[6], s[7]};
  r.fullFrame = true;
  havePieces_ = 0;  // a locate: the quarter frames start over
  lastPiece_ = -1;
  direction_ = 0;
  if (!inRange(r.time, r.rateCode)) {
    ++stats_.badTimes;
    return;
  }
  out.push_back(r);
}

void MtcDecoder::quarterFrame(uint8_t data, std::vector<MtcReading>& out) {
  ++stats_.quarterFrames;
  const int piece = data >> 4;  // data < 0x80, so 0..7
  const int step = lastPiece_ < 0 ? 0 : piece == (lastPiece_ + 1) % 8 ? 1 : piece == (lastPiece_ + 7) % 8 ? -1 : 2;
  lastPiece_ = piece;
  if (step == 2 || (step != 0 && direction_ != 0 && step != direction_)) {
    // A piece missing or the tape turned round: what was gathered belongs to no one time.
    if (havePieces_) ++stats_.brokenCycles;
    havePieces_ = 0;
  }
  direction_ = step == 2 ? 0 : step != 0 ? step : direction_;
  // A cycle starts at piece 0 running forward, at piece 7 running backward.
  if (piece == (direction_ < 0 ? 7 : 0)) havePieces_ = 0;
  pieces_[piece] = data & 0x0F;
  havePieces_ |= 1 << piece;
  if (direction_ != 0 && piece == (direction_ > 0 ? 7 : 0)) {
    if (havePieces_ == 0xFF)
      if (auto r = assemble(direction_)) out.push_back(*r);
    havePieces_ = 0;  // a partial first cycle (joined mid-way) just ends
  }
}

std::optional<MtcReading> MtcDecoder::assemble(int direction) {
  const uint8_t* p = pieces_;
  MtcReading r;
  r.rateCode = (p[7] >> 1) & 3;
  r.time = Timecode{(p[7] & 1) << 4 | p[6], (p[5] & 3) << 4 | p[4], (p[3] & 3) << 4 | p[2], (p[1] & 1) << 4 | p[0]};
  if (!inRange(r.time, r.rateCode)) {
    ++stats_.badTimes;
    return std::nullopt;
  }
  // Two frames went by while the eight pieces were sent.
  for (int i = 0; i < 2; ++i) {
    const auto next = stepFrame(r.time, r.rateCode, direction);
    if (!next) return std::nullopt;  // running past midnight: no reading rather than a wrong one
    r.time = *next;
  }
  return r;
}

}  // namespace haze
