// sACN E1.31 packet parsers. Offsets and rules are those of E1.31-2018 tables 4-1 (data), 4-2
// (synchronization), 4-3 (universe discovery), 5-1, 6-1 and 7-1; every PDU length must nest
// exactly inside the datagram, so a length field can never point a read past the end.
#include "shows/dmx/sacn.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace haze {

namespace {
constexpr uint8_t kAcnId[12] = {'A', 'S', 'C', '-', 'E', '1', '.', '1', '7', 0, 0, 0};
constexpr uint32_t kVectorRootData = 0x00000004;
constexpr uint32_t kVectorRootExtended = 0x00000008;
constexpr uint32_t kVectorDataPacket = 0x00000002;
constexpr uint8_t kVectorDmpSetProperty = 0x02;
constexpr uint8_t kAddressType = 0xA1;
constexpr size_t kRootEnd = 38;      // preamble .. CID
constexpr size_t kFramingEnd = 115;  // framing layer of a data packet
constexpr size_t kHeaderEnd = 126;   // DMP header and START code
constexpr uint32_t kVectorExtendedSync = 0x00000001;
constexpr uint32_t kVectorExtendedDiscovery = 0x00000002;
constexpr uint32_t kVectorDiscoveryUniverseList = 0x00000001;
constexpr size_t kExtendedHeaderEnd = 49;    // through a sync packet's reserved bytes
constexpr size_t kDiscoveryHeaderEnd = 120;  // through the discovery layer's last page

uint16_t be16(std::span<const uint8_t> d, size_t at) {
  return static_cast<uint16_t>((d[at] << 8) | d[at + 1]);
}
uint32_t be32(std::span<const uint8_t> d, size_t at) {
  return (uint32_t{d[at]} << 24) | (uint32_t{d[at + 1]} << 16) | (uint32_t{d[at + 2]} << 8) |
         uint32_t{d[at + 3]};
}
}  // namespace

std::string_view sacnStatusName(SacnStatus s) {
  switch (s) {
    case SacnStatus::Ok: return "ok";
    case SacnStatus::Ignored: return "ignored";
    case SacnStatus::TooShort: return "too_short";
    case SacnStatus::BadPreamble: return "bad_preamble";
    case SacnStatus::BadPostamble: return "bad_postamble";
    case SacnStatus::BadAcnId: return "bad_acn_id";
    case SacnStatus::BadRootLength: return "bad_root_length";
    case SacnStatus::BadRootVector: return "bad_root_vector";
    case SacnStatus::BadFramingLength: return "bad_framing_length";
    case SacnStatus::BadFramingVector: return "bad_framing_vector";
    case SacnStatus::BadPriority: return "bad_priority";
    case SacnStatus::BadUniverse: return "bad_universe";
    case SacnStatus::BadDmpLength: return "bad_dmp_length";
    case SacnStatus::BadDmpVector: return "bad_dmp_vector";
    case SacnStatus::BadAddressType: return "bad_address_type";
    case SacnStatus::BadFirstAddress: return "bad_first_address";
    case SacnStatus::BadIncrement: return "bad_increment";
    case SacnStatus::BadPropertyCount: return "bad_property_count";
    case SacnStatus::NotExtended: return "not_extended";
    case SacnStatus::BadExtendedLength: return "bad_extended_length";
    case SacnStatus::BadExtendedVector: return "bad_extended_vector";
    case SacnStatus::BadSyncAddress: return "bad_sync_address";
    case SacnStatus::BadDiscoveryLength: return "bad_discovery_length";
    case SacnStatus::BadDiscoveryVector: return "bad_discovery_vector";
    case SacnStatus::BadDiscoveryPage: return "bad_discovery_page";
    case SacnStatus::BadDiscoveryUniverse: return "bad_discovery_universe";
  }
  return "unknown";
}

Error sacnError(const SacnParse& p) { return sacnError(p.status, p.byte); }

Error sacnError(SacnStatus status, int byte) {
  const char* what = "";
  switch (status) {
    case SacnStatus::Ok: what = "a valid E1.31 data packet"; break;
    case SacnStatus::Ignored: what = "an extended packet, or a START code other than 0 and 0xDD: no levels"; break;
    case SacnStatus::TooShort: what = "the datagram ends inside a header; expected 126 bytes or more"; break;
    case SacnStatus::BadPreamble: what = "preamble size is not 0x0010"; break;
    case SacnStatus::BadPostamble: what = "post-amble size is not 0x0000"; break;
    case SacnStatus::BadAcnId: what = "not ACN: expected \"ASC-E1.17\" and three NULs in bytes 4-15"; break;
    case SacnStatus::BadRootLength: what = "root layer flags are not 0x7 or its length is not the datagram size - 16"; break;
    case SacnStatus::BadRootVector: what = "root vector is neither VECTOR_ROOT_E131_DATA (4) nor EXTENDED (8)"; break;
    case SacnStatus::BadFramingLength: what = "framing layer flags are not 0x7 or its length is not the root length - 22"; break;
    case SacnStatus::BadFramingVector: what = "framing vector is not VECTOR_E131_DATA_PACKET (2)"; break;
    case SacnStatus::BadPriority: what = "priority is above 200; expected 0..200"; break;
    case SacnStatus::BadUniverse: what = "universe outside 1..63999"; break;
    case SacnStatus::BadDmpLength: what = "DMP layer flags are not 0x7 or its length is not the framing length - 77"; break;
    case SacnStatus::BadDmpVector: what = "DMP vector is not VECTOR_DMP_SET_PROPERTY (2)"; break;
    case SacnStatus::BadAddressType: what = "address and data type is not 0xa1"; break;
    case SacnStatus::BadFirstAddress: what = "first property address is not 0"; break;
    case SacnStatus::BadIncrement: what = "address increment is not 1"; break;
    case SacnStatus::BadPropertyCount: what = "property value count does not match the DMP length or exceeds 513"; break;
    case SacnStatus::NotExtended: what = "root vector is not VECTOR_ROOT_E131_EXTENDED (8)"; break;
    case SacnStatus::BadExtendedLength: what = "extended framing flags are not 0x7 or its length does not nest in the root layer (a sync packet is 49 bytes)"; break;
    case SacnStatus::BadExtendedVector: what = "extended framing vector is neither SYNCHRONIZATION (1) nor DISCOVERY (2)"; break;
    case SacnStatus::BadSyncAddress: what = "synchronization address outside 1..63999"; break;
    case SacnStatus::BadDiscoveryLength: what = "universe discovery layer flags are not 0x7, or its length is not the framing length - 74 or is odd"; break;
    case SacnStatus::BadDiscoveryVector: what = "universe discovery vector is not UNIVERSE_LIST (1)"; break;
    case SacnStatus::BadDiscoveryPage: what = "discovery page is above the last page"; break;
    case SacnStatus::BadDiscoveryUniverse: what = "a listed universe is outside 1..63999, or more than 512 are listed"; break;
  }
  return Error{"", "byte " + std::to_string(byte), what};
}

uint32_t sacnMulticastGroup(int universe) {
  return (239u << 24) | (255u << 16) | (static_cast<uint32_t>(universe) & 0xFFFFu);
}

namespace {
// A PDU's flags & length word: top nibble 0x7, low 12 bits the PDU length; -1 for other flags.
int pduLength(std::span<const uint8_t> d, size_t at) {
  const uint16_t fl = be16(d, at);
  return (fl >> 12) == 0x7 ? (fl & 0x0FFF) : -1;
}

struct RootLayer {
  SacnStatus status = SacnStatus::Ok;
  size_t byte = 0;
  int length = 0;
  uint32_t vector = 0;
};

// The root layer every E1.31 packet starts with (table 4-1 / 6-1 / 6-2).
RootLayer readRoot(std::span<const uint8_t> d) {
  RootLayer r;
  auto fail = [&](SacnStatus s, size_t byte) {
    r.status = s;
    r.byte = byte;
    return r;
  };
  if (d.size() < kRootEnd) return fail(SacnStatus::TooShort, d.size());
  if (be16(d, 0) != 0x0010) return fail(SacnStatus::BadPreamble, 0);
  if (be16(d, 2) != 0x0000) return fail(SacnStatus::BadPostamble, 2);
  if (std::memcmp(d.data() + 4, kAcnId, sizeof kAcnId) != 0) return fail(SacnStatus::BadAcnId, 4);
  r.length = pduLength(d, 16);
  if (r.length < 0 || static_cast<size_t>(r.length) != d.size() - 16) {
    return fail(SacnStatus::BadRootLength, 16);
  }
  r.vector = be32(d, 18);
  if (r.vector != kVectorRootExtended && r.vector != kVectorRootData)
    return fail(SacnStatus::BadRootVector, 18);
  return r;
}
}  // namespace

SacnParse parseSacn(std::span<const uint8_t> d) {
  SacnParse r;
  auto fail = [&](SacnStatus s, size_t byte) {
    r.status = s;
    r.byte = static_cast<int>(byte);
    return r;
  };
  auto pduLength = [&](size_t at) { return haze::pduLength(d, at); };

  // Root layer.
  const RootLayer root = readRoot(d);
  if (root.status != SacnStatus::Ok) return fail(root.status, root.byte);
  const int rootLength = root.length;
  if (root.vector == kVectorRootExtended) return fail(SacnStatus::Ignored, 18);
  std::copy_n(d.data() + 22, 16, r.packet.cid.begin());

  // Framing layer.
  if (d.size() < kFramingEnd) return fail(SacnStatus::TooShort, d.size());
  const int framingLength = pduLength(38);
  if (framingLength != rootLength - 22) return fail(SacnStatus::BadFramingLength, 38);
  if (be32(d, 40) != kVectorDataPacket) return fail(SacnStatus::BadFramingVector, 40);
  const auto* name = reinterpret_cast<const char*>(d.data() + 44);
  r.packet.sourceName.assign(name, strnlen(name, 64));
  r.packet.priority = d[108];
  if (r.packet.priority > 200) return fail(SacnStatus::BadPriority, 108);
  r.packet.syncAddress = be16(d, 109);
  r.packet.sequence = d[111];
  r.packet.options = d[112];
  r.packet.universe = be16(d, 113);
  if (r.packet.universe < 1 || r.packet.universe > 63999) return fail(SacnStatus::BadUniverse, 113);

  // DMP layer.
  if (d.size() < kHeaderEnd) return fail(SacnStatus::TooShort, d.size());
  const int dmpLength = pduLength(115);
  if (dmpLength != framingLength - 77) return fail(SacnStatus::BadDmpLength, 115);
  if (d[117] != kVectorDmpSetProperty) return fail(SacnStatus::BadDmpVector, 117);
  if (d[118] != kAddressType) return fail(SacnStatus::BadAddressType, 118);
  if (be16(d, 119) != 0x0000) return fail(SacnStatus::BadFirstAddress, 119);
  if (be16(d, 121) != 0x0001) return fail(SacnStatus::BadIncrement, 121);
  const int count = be16(d, 123);
  if (count < 1 || count > 513 || count != dmpLength - 10) {
    return fail(SacnStatus::BadPropertyCount, 123);
  }
  r.packet.startCode = d[125];
  r.packet.slotCount = count - 1;
  std::copy_n(d.data() + kHeaderEnd, r.packet.slotCount, r.packet.slots.begin());
  if (r.packet.startCode == kSacnStartPerSlotPriority) {
    for (int i = 0; i < r.packet.slotCount; ++i)
      if (r.packet.slots[static_cast<size_t>(i)] > 200) return fail(SacnStatus::BadPriority, kHeaderEnd + static_cast<size_t>(i));
  } else if (r.packet.startCode != kSacnStartLevels) {
    // Other alternate START codes (text, RDM, manufacturer's...) are valid but not for haze.
    return fail(SacnStatus::Ignored, 125);
  }
  r.status = SacnStatus::Ok;
  r.byte = 0;
  return r;
}

SacnExtendedParse parseSacnExtended(std::span<const uint8_t> d) {
  SacnExtendedParse r;
  auto fail = [&](SacnStatus s, size_t byte) {
    r.status = s;
    r.byte = static_cast<int>(byte);
    return r;
  };
  const RootLayer root = readRoot(d);
  if (root.status != SacnStatus::Ok) return fail(root.status, root.byte);
  if (root.vector != kVectorRootExtended) return fail(SacnStatus::NotExtended, 18);
  if (d.size() < kExtendedHeaderEnd) return fail(SacnStatus::TooShort, d.size());
  const int framingLength = pduLength(d, 38);
  if (framingLength != root.length - 22) return fail(SacnStatus::BadExtendedLength, 38);
  const uint32_t vector = be32(d, 40);
  if (vector == kVectorExtendedSync) {
    // Sequence, synchronization address, 2 reserved bytes; nothing after them.
    if (framingLength != 11) return fail(SacnStatus::BadExtendedLength, 38);
    std::copy_n(d.data() + 22, 16, r.sync.cid.begin());
    r.sync.sequence = d[44];
    r.sync.syncAddress = be16(d, 45);
    if (r.sync.syncAddress < 1 || r.sync.syncAddress > 63999) return fail(SacnStatus::BadSyncAddress, 45);
    r.isSync = true;
    r.status = SacnStatus::Ok;
    return r;
  }
  if (vector != kVectorExtendedDiscovery) return fail(SacnStatus::BadExtendedVector, 40);
  // Framing: source name (64) and 4 reserved bytes, then the universe discovery layer.
  if (d.size() < kDiscoveryHeaderEnd) return fail(SacnStatus::TooShort, d.size());
  const int layerLength = pduLength(d, 112);
  if (layerLength != framingLength - 74 || layerLength < 8 || layerLength % 2 != 0)
    return fail(SacnStatus::BadDiscoveryLength, 112);
  if (be32(d, 114) != kVectorDiscoveryUniverseList) return fail(SacnStatus::BadDiscoveryVector, 114);
  SacnDiscoveryPacket& p = r.discovery;
  std::copy_n(d.data() + 22, 16, p.cid.begin());
  const auto* name = reinterpret_cast<const char*>(d.data() + 44);
  p.sourceName.assign(name, strnlen(name, 64));
  p.page = d[118];
  p.lastPage = d[119];
  if (p.page > p.lastPage) return fail(SacnStatus::BadDiscoveryPage, 118);
  const size_t count = static_cast<size_t>(layerLength - 8) / 2;
  if (count > 512) return fail(SacnStatus::BadDiscoveryUniverse, 112);
  p.universes.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const size_t at = kDiscoveryHeaderEnd + 2 * i;
    const uint16_t u = be16(d, at);
    if (u < 1 || u > 63999) return fail(SacnStatus::BadDiscoveryUniverse, at);
    p.universes.push_back(u);
  }
  r.isSync = false;
  r.status = SacnStatus::Ok;
  return r;
}

}  // namespace haze
