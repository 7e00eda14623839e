// MVR-xchange packets, TCP mode (docs/mvr.md, "MVR-xchange"): every message travels as a
// 28-byte header and a payload. The header, all fields big-endian:
//   uint32 magic 778682 | uint32 version 1 | uint32 packet number (zero based)
//   uint32 packet count | uint32 type (0 JSON, 1 MVR file) | uint64 payload length
// The decoder takes a byte stream in pieces of any size (partial reads), refuses a bad header
// before it holds a byte of its payload, and joins a message split over several packets.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <vector>

#include "fixtures/core/result.h"

namespace haze::xchange {

inline constexpr std::uint32_t kPacketMagic = 778682;
inline constexpr std::uint32_t kPacketVersion = 1;
inline constexpr std::size_t kHeaderBytes = 28;

enum class PayloadType : std::uint32_t { Json = 0, File = 1 };

// What a peer may send. A header that announces more is refused before anything is allocated,
// and the connection is closed; the figures are documented in docs/mvr.md.
struct Limits {
  std::uint64_t maxJsonBytes = 1ull << 20;    // one JSON message: 1 MiB
  std::uint64_t maxFileBytes = 256ull << 20;  // one MVR file: 256 MiB
  std::uint32_t maxPacketCount = 65536;       // packets one message is split into
};

struct Packet {
  PayloadType type = PayloadType::Json;
  std::vector<std::uint8_t> payload;  // every packet's payload, joined
};

// One message as one packet (number 0, count 1), as haze sends everything.
std::vector<std::uint8_t> encodePacket(PayloadType type, std::span<const std::uint8_t> payload);
std::vector<std::uint8_t> encodeJsonPacket(const std::string& json);
std::array<std::uint8_t, kHeaderBytes> encodeHeader(PayloadType type, std::uint64_t payloadBytes,
                                                    std::uint32_t number = 0, std::uint32_t count = 1);

class PacketDecoder {
 public:
  explicit PacketDecoder(Limits limits = {}) : limits_(limits) {}

  // Takes the next bytes of the stream. An Error (the place is "byte N" of the stream) means
  // the stream is broken: the caller closes the connection; later calls keep failing.
  Status feed(std::span<const std::uint8_t> bytes);
  // The next complete message, in order of arrival; false when none is waiting.
  bool next(Packet& out);
  // At the end of the stream: an Error when it ended inside a packet or a split message.
  Status finish() const;
  // Bytes of the current (unfinished) packet's payload held so far, and how many it announced.
  std::uint64_t payloadReceived() const { return payload_.size() - messageStart_; }
  std::uint64_t payloadExpected() const { return expected_; }

 private:
  Status header();
  Error fail(std::string message);

  Limits limits_;
  std::array<std::uint8_t, kHeaderBytes> head_{};
  std::size_t headFill_ = 0;
  bool inPayload_ = false;
  std::uint64_t expected_ = 0;      // payload bytes of the current packet
  std::size_t messageStart_ = 0;    // where the current packet's payload begins in payload_
  std::vector<std::uint8_t> payload_;  // the message being joined
  PayloadType type_ = PayloadType::Json;
  std::uint32_t number_ = 0, count_ = 0;  // of the current packet
  std::uint64_t offset_ = 0;        // stream bytes consumed, for error places
  std::deque<Packet> ready_;
  std::string broken_;              // set once the stream is refused
};

std::string payloadTypeName(PayloadType t);

}  // namespace haze::xchange
