// Art-Net 4 ArtDmx parsing (UDP port 6454). Only ArtDmx carries levels; every other valid
// Art-Net OpCode (ArtPoll, ArtSync...) is reported as Ignored, so that counters can tell a
// chatty network from a broken sender. Pure bytes in, no sockets, never throws.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "fixtures/core/result.h"

namespace haze {

inline constexpr uint16_t kArtNetPort = 6454;

// Why a datagram was not an ArtDmx packet haze can use. Ok = usable; Ignored = a valid Art-Net
// packet of another kind; the rest are malformed.
enum class ArtNetStatus {
  Ok,
  Ignored,          // another OpCode (ArtPoll, ArtSync, ArtAddress...)
  TooShort,         // fewer bytes than the header that field needs
  BadId,            // bytes 0-7 are not "Art-Net\0"
  OldProtocol,      // ProtVer (bytes 10-11) below 14
  BadLength,        // Length (bytes 16-17) odd, below 2 or above 512
  Truncated,        // the datagram holds fewer data bytes than Length says
};
inline constexpr int kArtNetStatusCount = 7;

std::string_view artNetStatusName(ArtNetStatus s);  // "bad_length"...: for counters and logs

struct ArtDmxPacket {
  uint8_t sequence = 0;      // 1..255; 0 = the sender does not sequence
  uint8_t physical = 0;      // informational
  uint16_t portAddress = 0;  // 15 bits: Net (7) | Sub-Net (4) | Universe (4)
  int length = 0;            // data slots present, 2..512
  std::array<uint8_t, 512> slots{};  // slot 1 at [0]; beyond length: 0

  // haze universes count from 1: Art-Net Port-Address 0 (0:0:0) is haze universe 1.
  int hazeUniverse() const { return static_cast<int>(portAddress) + 1; }
};

struct ArtDmxParse {
  ArtNetStatus status = ArtNetStatus::TooShort;
  int byte = 0;         // offset of the field that failed (for messages)
  ArtDmxPacket packet;  // valid when ok()
  bool ok() const { return status == ArtNetStatus::Ok; }
};

ArtDmxParse parseArtDmx(std::span<const uint8_t> datagram);
// ArtSync (OpCode 0x5200, ProtVer >= 14, at least 14 bytes): output the ArtDmx held since the
// previous ArtSync now (Art-Net 4 synchronous mode).
bool isArtSync(std::span<const uint8_t> datagram);
// A failed parse as an Error: place "byte N", what was wrong and what was expected.
Error artNetError(const ArtDmxParse& parse);

}  // namespace haze
