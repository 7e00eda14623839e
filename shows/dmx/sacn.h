// sACN (ANSI E1.31-2018) data packet parsing (UDP port 5568, multicast 239.255.hi.lo). Every
// field of the root, framing and DMP layers is validated; synchronization and discovery packets
// (VECTOR_ROOT_E131_EXTENDED) and alternate START codes are valid but carry no levels, so they
// come back as Ignored. Pure bytes in, no sockets, never throws.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "fixtures/core/result.h"

namespace haze {

inline constexpr uint16_t kSacnPort = 5568;

enum class SacnStatus {
  Ok,
  Ignored,             // extended packet (sync, discovery) or a START code other than 0
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
};
inline constexpr int kSacnStatusCount = 19;

std::string_view sacnStatusName(SacnStatus s);  // "bad_priority"...: for counters and logs

inline constexpr uint8_t kSacnOptionPreview = 0x80;         // Preview_Data
inline constexpr uint8_t kSacnOptionTerminated = 0x40;      // Stream_Terminated
inline constexpr uint8_t kSacnOptionForceSync = 0x20;       // Force_Synchronization

struct SacnPacket {
  std::array<uint8_t, 16> cid{};  // the source's component id (UUID)
  std::string sourceName;         // up to the first NUL of the 64-byte field
  uint8_t priority = 100;         // 0..200
  uint16_t syncAddress = 0;       // 0 = unsynchronized (haze does not synchronize)
  uint8_t sequence = 0;
  uint8_t options = 0;
  uint16_t universe = 1;          // 1..63999; haze universe = sACN universe
  uint8_t startCode = 0;
  int slotCount = 0;              // DMX slots after the START code, 0..512
  std::array<uint8_t, 512> slots{};  // slot 1 at [0]; beyond slotCount: 0

  bool preview() const { return options & kSacnOptionPreview; }
  bool terminated() const { return options & kSacnOptionTerminated; }
};

struct SacnParse {
  SacnStatus status = SacnStatus::TooShort;
  int byte = 0;       // offset of the field that failed (for messages)
  SacnPacket packet;  // valid when ok()
  bool ok() const { return status == SacnStatus::Ok; }
};

SacnParse parseSacn(std::span<const uint8_t> datagram);
// A failed parse as an Error: place "byte N", what was wrong and what was expected.
Error sacnError(const SacnParse& parse);

// The IPv4 multicast group of an sACN universe, host byte order: 239.255.hi.lo.
uint32_t sacnMulticastGroup(int universe);

}  // namespace haze
