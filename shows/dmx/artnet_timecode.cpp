// ArtTimeCode: ID, OpCode (low byte first), ProtVer, Filler, StreamId, Frames, Seconds, Minutes,
// Hours, Type (Art-Net 4 table for OpTimeCode).
#include "shows/dmx/artnet_timecode.h"

#include <cstring>

namespace haze {

namespace {
constexpr uint8_t kId[8] = {'A', 'r', 't', '-', 'N', 'e', 't', 0};
constexpr uint16_t kOpTimeCode = 0x9700;
constexpr double kFps[4] = {24.0, 25.0, 30000.0 / 1001.0, 30.0};
constexpr int kFrameLimit[4] = {24, 25, 30, 30};
}  // namespace

std::string_view artTimeCodeStatusName(ArtTimeCodeStatus s) {
  switch (s) {
    case ArtTimeCodeStatus::Ok: return "ok";
    case ArtTimeCodeStatus::NotTimeCode: return "not_timecode";
    case ArtTimeCodeStatus::TooShort: return "timecode_too_short";
    case ArtTimeCodeStatus::OldProtocol: return "timecode_old_protocol";
    case ArtTimeCodeStatus::BadType: return "timecode_bad_type";
    case ArtTimeCodeStatus::BadTime: return "timecode_bad_time";
  }
  return "unknown";
}

double ArtTimeCodePacket::fps() const { return kFps[type >= 0 && type < 4 ? type : 1]; }

ArtTimeCodeParse parseArtTimeCode(std::span<const uint8_t> d) {
  ArtTimeCodeParse r;
  auto fail = [&](ArtTimeCodeStatus s, int byte) {
    r.status = s;
    r.byte = byte;
    return r;
  };
  if (d.size() < 10 || std::memcmp(d.data(), kId, sizeof kId) != 0 ||
      static_cast<uint16_t>(d[8] | (d[9] << 8)) != kOpTimeCode)
    return fail(ArtTimeCodeStatus::NotTimeCode, 0);
  if (d.size() < 19) return fail(ArtTimeCodeStatus::TooShort, static_cast<int>(d.size()));
  if (((d[10] << 8) | d[11]) < 14) return fail(ArtTimeCodeStatus::OldProtocol, 10);
  if (d[18] > 3) return fail(ArtTimeCodeStatus::BadType, 18);
  r.packet.type = d[18];
  Timecode& t = r.packet.time;
  t.frames = d[14];
  t.seconds = d[15];
  t.minutes = d[16];
  t.hours = d[17];
  if (t.frames >= kFrameLimit[r.packet.type]) return fail(ArtTimeCodeStatus::BadTime, 14);
  if (t.seconds > 59) return fail(ArtTimeCodeStatus::BadTime, 15);
  if (t.minutes > 59) return fail(ArtTimeCodeStatus::BadTime, 16);
  if (t.hours > 23) return fail(ArtTimeCodeStatus::BadTime, 17);
  r.status = ArtTimeCodeStatus::Ok;
  return r;
}

}  // namespace haze
