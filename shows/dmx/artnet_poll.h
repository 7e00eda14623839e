// Art-Net 4 discovery: a console sends ArtPoll and lists the nodes that answer with
// ArtPollReply; many consoles send ArtDmx unicast only to nodes that answered. haze answers as a
// visualiser (Style StVisual) whose output ports are the show's patched universes, four to a
// reply (Art-Net's BindIndex pages). Pure bytes, no sockets.
#pragma once

#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace haze {

inline constexpr size_t kArtPollReplySize = 239;

// An ArtPoll (OpCode 0x2000, ProtVer >= 14) from a controller.
bool isArtPoll(std::span<const uint8_t> datagram);

struct ArtNodeInfo {
  uint32_t ipv4 = 0;          // host order: the address the console reaches haze at
  std::string shortName = "haze";               // at most 17 characters go out
  std::string longName = "haze visualiser";     // at most 63
  std::set<int> hazeUniverses;                  // 1-based; Art-Net Port-Address = universe - 1
};

// The replies for a poll: one per Net/Sub-Net page of up to four universes (at least one, with no
// ports, when nothing is patched), BindIndex 1, 2, ... Universes outside Art-Net's 15-bit
// Port-Address range are left out.
std::vector<std::vector<uint8_t>> artPollReplies(const ArtNodeInfo& node);

}  // namespace haze
