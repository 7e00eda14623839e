// Universe synchronisation: frames that belong to a sync group are held and go into the merge
// together when the group's sync packet arrives, so a console's universes change on the same
// frame. Two kinds of group:
//   sACN (E1.31 6.2.4, 6.3, 11.2): a data packet with a non-zero Synchronization Address S is
//     held until a Synchronization Packet for S; without one for E131_NETWORK_DATA_LOSS_TIMEOUT
//     (2.5 s) the data is applied as it arrives again, unless its Force_Synchronization option
//     is set (then it stays held until synchronisation resumes).
//   Art-Net 4 (ArtSync): one group per controller IP address. Once an ArtSync has come from an
//     address, the ArtDmx from that address are held until its next ArtSync; after 4 s without
//     one, they are applied as they arrive again. An ArtSync never releases another address's.
// Only the newest frame per source, universe and kind (levels, per-slot priority) is kept: that
// is what the merge would end with. Bounded: at most maxHeld frames; time is passed in.
// Groups beyond maxGroups are not tracked (their frames are Full: counted, not merged).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "shows/dmx/dmx_merge.h"

namespace haze {

struct SyncGroup {
  DmxProtocol protocol = DmxProtocol::Sacn;
  int address = 0;  // sACN synchronization universe; 0 for Art-Net
  uint32_t sender = 0;  // Art-Net: the controller's IPv4 address (host order); 0 for sACN
  auto operator<=>(const SyncGroup&) const = default;
};

// A frame with its own copy of the slots, for holding.
struct HeldFrame {
  DmxFrame frame;  // frame.slots is not used: view() points it at `data`
  DmxBuffer data{};
  size_t count = 0;
  DmxFrame view() const {
    DmxFrame f = frame;
    f.slots = std::span<const uint8_t>(data.data(), count);
    return f;
  }
};

struct SyncOptions {
  double sacnTimeoutS = 2.5;  // E131_NETWORK_DATA_LOSS_TIMEOUT
  double artNetTimeoutS = 4.0;  // Art-Net 4: back to immediate output after 4 s without ArtSync
  size_t maxHeld = 4096;
  size_t maxGroups = 256;
};

class SyncGate {
 public:
  explicit SyncGate(SyncOptions options = {});

  enum class Verdict { ApplyNow, Held, Replaced, Late, Full };  // Replaced: held, over an older one
  // Holds the frame when its group is synchronised (or forced); ApplyNow: merge it at once.
  Verdict offer(const SyncGroup& group, const DmxFrame& frame, bool forceSync, double nowS);
  // A sync packet: the group is synchronised from now on; returns its held frames, oldest first.
  std::vector<HeldFrame> sync(const SyncGroup& group, double nowS);
  // Groups whose sync stopped: the held frames of those not forced, to merge now.
  std::vector<HeldFrame> expire(double nowS);

  // Drops the frames held for a source's universe (it sent Stream_Terminated); returns how many.
  size_t forget(const DmxSourceId& source, int universe);

  bool synchronised(const SyncGroup& group, double nowS) const;
  size_t heldCount() const { return heldCount_; }
  // The sACN synchronization addresses data has named, in order (for joining their groups).
  const std::vector<int>& sacnSyncAddresses() const { return sacnAddresses_; }

 private:
  using Key = std::tuple<DmxSourceId, int, bool>;  // source, universe, per-slot priority
  struct Group {
    std::optional<double> lastSyncS;
    bool forced = false;  // the newest held sACN frame asked for Force_Synchronization
    std::map<Key, std::pair<uint64_t, HeldFrame>> held;  // arrival number, frame
  };
  double timeout(const SyncGroup& g) const;
  void noteAddress(const SyncGroup& g);
  std::vector<HeldFrame> take(Group& g);

  SyncOptions options_;
  std::map<SyncGroup, Group> groups_;
  size_t heldCount_ = 0;
  uint64_t arrivals_ = 0;
  std::vector<int> sacnAddresses_;
};

}  // namespace haze
