#include "shows/xchange/packet.h"

#include <algorithm>

namespace haze::xchange {
namespace {

void putBe(std::uint8_t* at, std::uint64_t v, int bytes) {
  for (int i = bytes - 1; i >= 0; --i, v >>= 8) at[i] = static_cast<std::uint8_t>(v & 0xff);
}

std::uint64_t getBe(const std::uint8_t* at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | at[i];
  return v;
}

std::string mib(std::uint64_t bytes) {
  return bytes % (1ull << 20) == 0 ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

}  // namespace

std::string payloadTypeName(PayloadType t) { return t == PayloadType::Json ? "JSON" : "MVR file"; }

std::array<std::uint8_t, kHeaderBytes> encodeHeader(PayloadType type, std::uint64_t payloadBytes, std::uint32_t number,
                                                    std::uint32_t count) {
  std::array<std::uint8_t, kHeaderBytes> h{};
  putBe(&h[0], kPacketMagic, 4);
  putBe(&h[4], kPacketVersion, 4);
  putBe(&h[8], number, 4);
  putBe(&h[12], count, 4);
  putBe(&h[16], static_cast<std::uint32_t>(type), 4);
  putBe(&h[20], payloadBytes, 8);
  return h;
}

std::vector<std::uint8_t> encodePacket(PayloadType type, std::span<const std::uint8_t> payload) {
  const auto h = encodeHeader(type, payload.size());
  std::vector<std::uint8_t> out(h.begin(), h.end());
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::vector<std::uint8_t> encodeJsonPacket(const std::string& json) {
  return encodePacket(PayloadType::Json,
                      std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(json.data()), json.size()));
}

Error PacketDecoder::fail(std::string message) {
  broken_ = message;
  payload_.clear();
  payload_.shrink_to_fit();
  return Error{"", "byte " + std::to_string(offset_), std::move(message)};
}

// Checks the header just completed; nothing of the payload is allocated before this passes.
Status PacketDecoder::header() {
  const std::uint64_t magic = getBe(&head_[0], 4), version = getBe(&head_[4], 4);
  const auto number = static_cast<std::uint32_t>(getBe(&head_[8], 4));
  const auto count = static_cast<std::uint32_t>(getBe(&head_[12], 4));
  const std::uint64_t type = getBe(&head_[16], 4), length = getBe(&head_[20], 8);
  if (magic != kPacketMagic)
    return fail("not an MVR-xchange packet: header " + std::to_string(magic) + ", expected " + std::to_string(kPacketMagic));
  if (version != kPacketVersion)
    return fail("MVR-xchange packet version " + std::to_string(version) + " is not supported; expected 1");
  if (type > 1) return fail("unknown MVR-xchange packet type " + std::to_string(type) + "; expected 0 (JSON) or 1 (MVR file)");
  if (count == 0 || count > limits_.maxPacketCount || number >= count)
    return fail("packet " + std::to_string(number) + " of " + std::to_string(count) + " is not a packet of a message (count 1.." +
                std::to_string(limits_.maxPacketCount) + ", number below it)");
  const auto t = static_cast<PayloadType>(type);
  const bool continuing = payload_.size() > 0 || count_ > 1;
  if (continuing && (number != number_ + 1 || count != count_ || t != type_))
    return fail("packet " + std::to_string(number) + " of " + std::to_string(count) + " (" + payloadTypeName(t) +
                ") does not continue packet " + std::to_string(number_) + " of " + std::to_string(count_));
  if (!continuing && number != 0)
    return fail("a message starts with packet " + std::to_string(number) + "; expected packet 0");
  const std::uint64_t limit = t == PayloadType::Json ? limits_.maxJsonBytes : limits_.maxFileBytes;
  if (length > limit || payload_.size() + length > limit)
    return fail("the " + payloadTypeName(t) + " payload of " + std::to_string(payload_.size() + length) +
                " bytes is over the limit of " + mib(limit));
  type_ = t;
  number_ = number;
  count_ = count;
  expected_ = length;
  messageStart_ = payload_.size();
  inPayload_ = true;
  return Ok{};
}

Status PacketDecoder::feed(std::span<const std::uint8_t> bytes) {
  if (!broken_.empty()) return Error{"", "", broken_};
  std::size_t at = 0;
  while (at < bytes.size() || (inPayload_ && payloadReceived() == expected_)) {
    if (!inPayload_) {
      const std::size_t take = std::min(kHeaderBytes - headFill_, bytes.size() - at);
      std::copy_n(bytes.begin() + static_cast<long>(at), take, head_.begin() + static_cast<long>(headFill_));
      headFill_ += take;
      at += take;
      offset_ += take;
      if (headFill_ < kHeaderBytes) break;
      headFill_ = 0;
      if (Status s = header(); !s) return s;
      continue;
    }
    // Grows with what arrives: a header that announces much and sends little costs little.
    const std::uint64_t want = expected_ - payloadReceived();
    const std::size_t take = static_cast<std::size_t>(std::min<std::uint64_t>(want, bytes.size() - at));
    payload_.insert(payload_.end(), bytes.begin() + static_cast<long>(at), bytes.begin() + static_cast<long>(at + take));
    at += take;
    offset_ += take;
    if (payloadReceived() < expected_) break;
    inPayload_ = false;
    if (number_ + 1 == count_) {
      ready_.push_back(Packet{type_, std::move(payload_)});
      payload_ = {};
      count_ = 0;
      number_ = 0;
    }
    messageStart_ = payload_.size();
    expected_ = 0;
  }
  return Ok{};
}

bool PacketDecoder::next(Packet& out) {
  if (ready_.empty()) return false;
  out = std::move(ready_.front());
  ready_.pop_front();
  return true;
}

Status PacketDecoder::finish() const {
  if (!broken_.empty()) return Error{"", "", broken_};
  if (headFill_ > 0)
    return Error{"", "byte " + std::to_string(offset_),
                 "truncated packet: the stream ended after " + std::to_string(headFill_) + " of 28 header bytes"};
  if (inPayload_)
    return Error{"", "byte " + std::to_string(offset_),
                 "truncated packet: the stream ended after " + std::to_string(payloadReceived()) + " of " +
                     std::to_string(expected_) + " payload bytes"};
  if (count_ > 1)
    return Error{"", "byte " + std::to_string(offset_),
                 "truncated message: the stream ended after packet " + std::to_string(number_) + " of " +
                     std::to_string(count_)};
  return Ok{};
}

}  // namespace haze::xchange
