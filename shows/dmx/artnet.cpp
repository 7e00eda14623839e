// Art-Net 4 ArtDmx parser: header fields checked in wire order, every read bounds-checked
// against the datagram, so any byte string is safe to hand in.
#include "shows/dmx/artnet.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace haze {

namespace {
constexpr uint8_t kId[8] = {'A', 'r', 't', '-', 'N', 'e', 't', 0};
constexpr uint16_t kOpDmx = 0x5000;
constexpr uint16_t kOpSync = 0x5200;
constexpr int kHeaderBytes = 18;
constexpr int kMinProtVer = 14;
}  // namespace

std::string_view artNetStatusName(ArtNetStatus s) {
  switch (s) {
    case ArtNetStatus::Ok: return "ok";
    case ArtNetStatus::Ignored: return "other_opcode";
    case ArtNetStatus::TooShort: return "too_short";
    case ArtNetStatus::BadId: return "bad_id";
    case ArtNetStatus::OldProtocol: return "old_protocol";
    case ArtNetStatus::BadLength: return "bad_length";
    case ArtNetStatus::Truncated: return "truncated";
  }
  return "unknown";
}

Error artNetError(const ArtDmxParse& p) {
  const char* what = "";
  switch (p.status) {
    case ArtNetStatus::Ok: what = "a valid ArtDmx packet"; break;
    case ArtNetStatus::Ignored: what = "an Art-Net OpCode other than OpDmx (0x5000), which carries no levels"; break;
    case ArtNetStatus::TooShort: what = "the datagram ends inside the header; expected 18 header bytes"; break;
    case ArtNetStatus::BadId: what = "not Art-Net: expected \"Art-Net\" and a NUL in bytes 0-7"; break;
    case ArtNetStatus::OldProtocol: what = "protocol version below 14; expected Art-Net 4 (ProtVer >= 14)"; break;
    case ArtNetStatus::BadLength: what = "DMX length is odd or outside 2..512; expected an even length 2..512"; break;
    case ArtNetStatus::Truncated: what = "the datagram holds fewer DMX bytes than its Length field says"; break;
  }
  return Error{"", "byte " + std::to_string(p.byte), what};
}

ArtDmxParse parseArtDmx(std::span<const uint8_t> d) {
  ArtDmxParse r;
  auto fail = [&](ArtNetStatus s, int byte) {
    r.status = s;
    r.byte = byte;
    return r;
  };
  if (d.size() < 10) return fail(ArtNetStatus::TooShort, static_cast<int>(d.size()));
  if (std::memcmp(d.data(), kId, sizeof kId) != 0) return fail(ArtNetStatus::BadId, 0);
  const uint16_t opCode = static_cast<uint16_t>(d[8] | (d[9] << 8));  // little-endian
  if (opCode != kOpDmx) return fail(ArtNetStatus::Ignored, 8);
  if (d.size() < kHeaderBytes) return fail(ArtNetStatus::TooShort, static_cast<int>(d.size()));
  const int protVer = (d[10] << 8) | d[11];  // big-endian, unlike OpCode
  if (protVer < kMinProtVer) return fail(ArtNetStatus::OldProtocol, 10);
  const int length = (d[16] << 8) | d[17];
  if (length < 2 || length > 512 || length % 2 != 0) return fail(ArtNetStatus::BadLength, 16);
  if (d.size() < static_cast<size_t>(kHeaderBytes + length)) {
    return fail(ArtNetStatus::Truncated, static_cast<int>(d.size()));
  }
  r.packet.sequence = d[12];
  r.packet.physical = d[13];
  // SubUni is the low byte; Net holds the top 7 bits (its bit 7 is not part of the address).
  r.packet.portAddress = static_cast<uint16_t>(((d[15] & 0x7F) << 8) | d[14]);
  r.packet.length = length;
  std::copy_n(d.data() + kHeaderBytes, length, r.packet.slots.begin());
  r.status = ArtNetStatus::Ok;
  r.byte = 0;
  return r;
}

bool isArtSync(std::span<const uint8_t> d) {
  if (d.size() < 14 || std::memcmp(d.data(), kId, sizeof kId) != 0) return false;
  const uint16_t opCode = static_cast<uint16_t>(d[8] | (d[9] << 8));
  return opCode == kOpSync && ((d[10] << 8) | d[11]) >= kMinProtVer;
}

}  // namespace haze
