// ArtPollReply packets (see artnet_poll.h). Field offsets follow the Art-Net 4 ArtPollReply
// table; multi-byte fields are big-endian unless the table says low byte first (OpCode, Port).
#include "shows/dmx/artnet_poll.h"

#include <algorithm>
#include <cstring>
#include <map>

namespace haze {

namespace {

constexpr char kId[8] = {'A', 'r', 't', '-', 'N', 'e', 't', 0};
constexpr uint16_t kOpPoll = 0x2000, kOpPollReply = 0x2100;
constexpr int kMaxPortAddress = 0x7FFF;
constexpr uint8_t kStyleVisualiser = 0x06;

void putName(std::vector<uint8_t>& p, size_t at, size_t size, const std::string& name) {
  const size_t n = std::min(name.size(), size - 1);  // always NUL-terminated
  std::memcpy(p.data() + at, name.data(), n);
}

}  // namespace

bool isArtPoll(std::span<const uint8_t> d) {
  if (d.size() < 14 || std::memcmp(d.data(), kId, 8) != 0) return false;
  const uint16_t op = static_cast<uint16_t>(d[8] | (d[9] << 8));
  const uint16_t version = static_cast<uint16_t>((d[10] << 8) | d[11]);
  return op == kOpPoll && version >= 14;
}

std::vector<std::vector<uint8_t>> artPollReplies(const ArtNodeInfo& node) {
  // Port-Addresses by page: Net and Sub-Net are per reply, the low four bits per port.
  std::map<int, std::vector<int>> pages;  // (Net << 4 | Sub-Net) -> universes (low nibble)
  for (int u : node.hazeUniverses) {
    const int pa = u - 1;
    if (pa < 0 || pa > kMaxPortAddress) continue;
    pages[pa >> 4].push_back(pa & 0xF);
  }
  std::vector<std::pair<int, std::vector<int>>> replies;  // page, up to four ports
  for (const auto& [page, ports] : pages)
    for (size_t i = 0; i < ports.size(); i += 4)
      replies.push_back({page, std::vector<int>(ports.begin() + i, ports.begin() + std::min(ports.size(), i + 4))});
  if (replies.empty()) replies.push_back({0, {}});

  std::vector<std::vector<uint8_t>> out;
  for (size_t r = 0; r < replies.size(); ++r) {
    const auto& [page, ports] = replies[r];
    std::vector<uint8_t> p(kArtPollReplySize, 0);
    std::memcpy(p.data(), kId, 8);
    p[8] = kOpPollReply & 0xFF;
    p[9] = kOpPollReply >> 8;
    p[10] = static_cast<uint8_t>(node.ipv4 >> 24);
    p[11] = static_cast<uint8_t>(node.ipv4 >> 16);
    p[12] = static_cast<uint8_t>(node.ipv4 >> 8);
    p[13] = static_cast<uint8_t>(node.ipv4);
    p[14] = 6454 & 0xFF;  // Port, low byte first
    p[15] = 6454 >> 8;
    p[18] = static_cast<uint8_t>((page >> 4) & 0x7F);  // NetSwitch
    p[19] = static_cast<uint8_t>(page & 0x0F);         // SubSwitch
    p[23] = 0xD0;  // Status1: indicators normal, Port-Address set locally (from the show's patch)
    putName(p, 26, 18, node.shortName);
    putName(p, 44, 64, node.longName);
    putName(p, 108, 64, "#0001 [0000] haze is listening");
    p[173] = static_cast<uint8_t>(ports.size());  // NumPorts (low byte)
    for (size_t k = 0; k < ports.size(); ++k) {
      p[174 + k] = 0x80;                                 // PortTypes: outputs DMX512 from Art-Net
      p[190 + k] = static_cast<uint8_t>(ports[k]);        // SwOut
    }
    p[200] = kStyleVisualiser;
    p[207] = p[10];  // BindIp: this address is the root device
    p[208] = p[11];
    p[209] = p[12];
    p[210] = p[13];
    p[211] = static_cast<uint8_t>(r + 1);  // BindIndex
    p[212] = 0x08;  // Status2: 15-bit Port-Addresses (Art-Net 3 and 4)
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace haze
