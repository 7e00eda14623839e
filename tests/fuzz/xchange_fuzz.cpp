// Fuzz harness: a TCP byte stream from an MVR-xchange peer through the packet decoder (cut into
// pieces, as reads return them) and each message through a station that has one file request
// outstanding, so file packets reach the MVR archive check. Accepted: the stream decodes to the
// end and no message or file closes the connection.
#include <algorithm>

#include "fuzz/harness.h"
#include "shows/xchange/packet.h"
#include "shows/xchange/station.h"

namespace haze::fuzz {

bool acceptXchange(const uint8_t* data, size_t size) {
  using namespace haze::xchange;
  Station station({"fuzz", "11111111-2222-4333-8444-555555555555"});
  station.setRequestCommits(true);
  CommitInfo offered;
  offered.fileUuid = "a7669ff9-bd61-4486-aea6-c190f8ba6b8c";
  offered.fileSize = 10;
  station.offer(offered);
  (void)station.request(1, "", "");
  PacketDecoder decoder;
  // Pieces of a size the input's length picks: the decoder must not care where reads end.
  const size_t piece = 1 + size % 13;
  for (size_t at = 0; at < size; at += piece) {
    if (!decoder.feed(std::span<const uint8_t>(data + at, std::min(piece, size - at)))) return false;
    Packet p;
    while (decoder.next(p)) {
      const Reaction r = station.receive(1, p);
      for (const Message& m : r.replies) (void)toJson(m);
      if (r.request) (void)toJson(*r.request);
      if (r.close) return false;
    }
  }
  return static_cast<bool>(decoder.finish());
}

}  // namespace haze::fuzz

HAZE_FUZZ_ENTRY(acceptXchange)
