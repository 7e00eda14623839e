// Art-Net 4 ArtTimeCode (OpCode 0x9700): a console or timecode source sends the current SMPTE
// time, usually once a frame. Pure bytes in, never throws.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "shows/timecode.h"

namespace haze {

enum class ArtTimeCodeStatus {
  Ok,
  NotTimeCode,  // not Art-Net, or another OpCode
  TooShort,     // fewer than the 19 bytes of the packet
  OldProtocol,  // ProtVer below 14
  BadType,      // byte 18 above 3
  BadTime,      // a field out of range for the frame rate, or 24 h and beyond
};

std::string_view artTimeCodeStatusName(ArtTimeCodeStatus s);  // "bad_time"...

struct ArtTimeCodePacket {
  Timecode time;
  int type = 1;  // 0 Film (24 fps), 1 EBU (25), 2 DF (29.97 drop-frame), 3 SMPTE (30)
  double fps() const;
};

struct ArtTimeCodeParse {
  ArtTimeCodeStatus status = ArtTimeCodeStatus::NotTimeCode;
  int byte = 0;
  ArtTimeCodePacket packet;
  bool ok() const { return status == ArtTimeCodeStatus::Ok; }
};

ArtTimeCodeParse parseArtTimeCode(std::span<const uint8_t> datagram);

}  // namespace haze
