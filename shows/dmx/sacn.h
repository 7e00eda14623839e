// sACN (ANSI E1.31-2018) parsing (UDP port 5568, multicast 239.255.hi.lo). Data packets: every
// field of the root, framing and DMP layers is validated; START code 0 (levels) and 0xDD
// (per-slot priorities) are used, other START codes are valid but ignored. Extended packets
// (VECTOR_ROOT_E131_EXTENDED: synchronization and universe discovery) come back from parseSacn
// as Ignored and are read by parseSacnExtended. Pure bytes in, no sockets, never throws.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fixtures/core/result.h"

namespace haze {

inline constexpr uint16_t kSacnPort = 5568;

enum class SacnStatus {
  Ok,
  Ignored,             // extended packet (parseSacnExtended) or a START code other than 0, 0xDD
  TooShort,            // fewer bytes than the layer that was being read
  BadPreamble,         // bytes 0-1 not 0x0010
  BadPostamble,        // bytes 2-3 not 0x0000
  BadAcnId,            // bytes 4-15 not "ASC-E1.17\0\0\0"
  BadRootLength,       // bytes 16-17: flags not 0x7 or length not the datagram size - 16
  BadRootVector,       // bytes 18-21 neither DATA (4) nor EXTENDED (8)
  BadFramingLength,    // bytes 38-39: flags not 0x7 or length not root length - 22
  BadFramingVector,    // bytes 40-43 not VECTOR_E131_DATA_PACKET (2)
  BadPriority,         // byte 108 above 200
  BadUniverse,         // bytes 113-114 outside 1..63999
  BadDmpLength,        // bytes 115-116: flags not 0x7 or length not framing length - 77
  BadDmpVector,        // byte 117 not VECTOR_DMP_SET_PROPERTY (2)
  BadAddressType,      // byte 118 not 0xa1
  BadFirstAddress,     // bytes 119-120 not 0
  BadIncrement,        // bytes 121-122 not 1
  BadPropertyCount,    // bytes 123-124 not 1..513 or not DMP length - 10
  // Extended packets (parseSacnExtended).
  NotExtended,         // bytes 18-21 not VECTOR_ROOT_E131_EXTENDED (8): a data packet
  BadExtendedLength,   // bytes 38-39: flags not 0x7 or length not root length - 22, or not 11 (sync)
  BadExtendedVector,   // bytes 40-43 neither SYNCHRONIZATION (1) nor DISCOVERY (2)
  BadSyncAddress,      // bytes 45-46 outside 1..63999
  BadDiscoveryLength,  // bytes 112-113: flags not 0x7, length not framing length - 74 or odd
  BadDiscoveryVector,  // bytes 114-117 not VECTOR_UNIVERSE_DISCOVERY_UNIVERSE_LIST (1)
  BadDiscoveryPage,    // byte 118 (page) above byte 119 (last page)
  BadDiscoveryUniverse,// a listed universe outside 1..63999, or more than 512 listed
};
inline constexpr int kSacnStatusCount = 27;

std::string_view sacnStatusName(SacnStatus s);  // "bad_priority"...: for counters and logs

inline constexpr uint8_t kSacnOptionPreview = 0x80;         // Preview_Data
inline constexpr uint8_t kSacnOptionTerminated = 0x40;      // Stream_Terminated
inline constexpr uint8_t kSacnOptionForceSync = 0x20;       // Force_Synchronization
inline constexpr uint8_t kSacnStartLevels = 0x00;           // NULL START code: dimmer levels
inline constexpr uint8_t kSacnStartPerSlotPriority = 0xDD;  // per-slot priorities 0..200
inline constexpr uint16_t kSacnDiscoveryUniverse = 64214;   // E131_DISCOVERY_UNIVERSE

struct SacnPacket {
  std::array<uint8_t, 16> cid{};  // the source's component id (UUID)
  std::string sourceName;         // up to the first NUL of the 64-byte field
  uint8_t priority = 100;         // 0..200
  uint16_t syncAddress = 0;       // 0 = unsynchronized; else held until that universe's sync
  uint8_t sequence = 0;
  uint8_t options = 0;
  uint16_t universe = 1;          // 1..63999; haze universe = sACN universe
  uint8_t startCode = 0;          // kSacnStartLevels or kSacnStartPerSlotPriority when ok()
  int slotCount = 0;              // DMX slots after the START code, 0..512
  std::array<uint8_t, 512> slots{};  // slot 1 at [0]; beyond slotCount: 0

  bool preview() const { return options & kSacnOptionPreview; }
  bool terminated() const { return options & kSacnOptionTerminated; }
  bool forceSync() const { return options & kSacnOptionForceSync; }
};

struct SacnParse {
  SacnStatus status = SacnStatus::TooShort;
  int byte = 0;       // offset of the field that failed (for messages)
  SacnPacket packet;  // valid when ok()
  bool ok() const { return status == SacnStatus::Ok; }
};

// A per-slot priority packet (START code 0xDD) with a slot above 200 is BadPriority at that slot.
SacnParse parseSacn(std::span<const uint8_t> datagram);
// A failed parse as an Error: place "byte N", what was wrong and what was expected.
Error sacnError(const SacnParse& parse);
Error sacnError(SacnStatus status, int byte);

// E1.31 6.3: "apply the data held for universes synchronized on syncAddress now".
struct SacnSyncPacket {
  std::array<uint8_t, 16> cid{};
  uint8_t sequence = 0;
  uint16_t syncAddress = 1;  // 1..63999
};

// E1.31 8: one page of the universes a source sends (sent every 10 s on universe 64214).
struct SacnDiscoveryPacket {
  std::array<uint8_t, 16> cid{};
  std::string sourceName;
  uint8_t page = 0, lastPage = 0;
  std::vector<uint16_t> universes;  // up to 512, each 1..63999
};

struct SacnExtendedParse {
  SacnStatus status = SacnStatus::TooShort;  // Ok, NotExtended, or why the packet is malformed
  int byte = 0;
  bool isSync = false;  // else discovery
  SacnSyncPacket sync;
  SacnDiscoveryPacket discovery;
  bool ok() const { return status == SacnStatus::Ok; }
};

SacnExtendedParse parseSacnExtended(std::span<const uint8_t> datagram);

// The IPv4 multicast group of an sACN universe, host byte order: 239.255.hi.lo.
uint32_t sacnMulticastGroup(int universe);

}  // namespace haze
