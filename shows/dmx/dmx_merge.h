// Merging DMX sources into one 512-slot buffer per haze universe, the way E1.31 receivers do:
// per slot the live sources of the highest priority win and are merged Highest-Takes-Precedence.
// A source's priority is its universe priority for every slot, or, while it sends per-slot
// priorities (sACN START code 0xDD), that slot's priority, 0 meaning "not driven by this source"; a source leaves on Stream_Terminated or after its data-loss timeout
// (E1.31: 2.5 s; Art-Net has no priority, merges at 100 and times out after 10 s, its merge
// rule); packets whose sequence number is late by less than 20 are discarded (E1.31 6.7.2).
// Time is passed in (seconds on any monotonic clock), so tests inject it. Bounded: a fixed
// number of sources per universe and of universes.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace haze {

enum class DmxProtocol { Sacn, ArtNet };

using DmxBuffer = std::array<uint8_t, 512>;  // slot 1 at [0]

// Who sent a stream: sACN by CID, Art-Net by the sender's IPv4 address and port.
struct DmxSourceId {
  DmxProtocol protocol = DmxProtocol::Sacn;
  std::array<uint8_t, 16> bytes{};
  auto operator<=>(const DmxSourceId&) const = default;

  static DmxSourceId sacn(const std::array<uint8_t, 16>& cid);
  static DmxSourceId artNet(uint32_t ipv4HostOrder, uint16_t port);
  std::string str() const;  // CID as a UUID, or "a.b.c.d:port"
};

// One packet's worth of levels for one universe, already parsed.
struct DmxFrame {
  DmxSourceId source;
  std::string name;            // sACN source name; "" for Art-Net
  int universe = 1;            // haze universe, from 1
  int priority = 100;          // 0..200
  std::optional<uint8_t> sequence;  // empty: the sender does not sequence (Art-Net 0)
  bool terminated = false;     // sACN Stream_Terminated: the source leaves, its levels are ignored
  bool perSlotPriority = false;  // slots are per-slot priorities (START code 0xDD), not levels
  std::span<const uint8_t> slots;  // up to 512; missing slots count as 0
};

enum class MergeVerdict {
  Accepted,
  LateSequence,      // (new - last) in (-20, 0]: out of order or duplicate
  Terminated,        // the source said goodbye (counted, not an error)
  UnwatchedUniverse, // no patched fixture listens to this universe
  SourcesExceeded,   // more sources than the universe or the merger can track
};

enum class LossPolicy {
  HoldLastLook,  // a universe whose sources are all gone keeps its last merged levels
  Blackout,      // ... or the light goes out: intensity 0, every other attribute held (what a
                 // moving light set to "blackout on DMX loss" does: it closes, its head stays put)
};

struct MergeOptions {
  double sacnTimeoutS = 2.5;    // E131_NETWORK_DATA_LOSS_TIMEOUT
  double artNetTimeoutS = 10.0; // Art-Net merge: a source silent this long leaves the merge
  LossPolicy onLoss = LossPolicy::HoldLastLook;
  std::set<int> universes;      // the universes to track; empty = any (up to maxUniverses)
  int maxSourcesPerUniverse = 8;
  int maxUniverses = 256;
};

struct DmxSourceInfo {
  DmxSourceId id;
  std::string name;
  int universe = 0;
  int priority = 0;
  bool winning = false;  // at the top priority of at least one slot, so part of its HTP merge
  bool perSlotPriority = false;  // sending per-slot priorities (0xDD)
  double lastSeenS = 0.0;
};

class DmxMerger {
 public:
  explicit DmxMerger(MergeOptions options = {});

  MergeVerdict submit(const DmxFrame& frame, double nowS);
  // Drops sources silent longer than their timeout; returns how many left.
  int expire(double nowS);

  // The merged levels of a universe (the last ones after a loss); nullptr while it never had data.
  const DmxBuffer* universe(int universe) const;
  // Whether frames for this universe are tracked at all (options.universes).
  bool watches(int universe) const;
  // True while a universe has lost every source under LossPolicy::Blackout: its fixtures are dark.
  bool blackedOut(int universe) const;
  std::vector<int> activeUniverses() const;
  std::vector<DmxSourceInfo> sources() const;
  // Whether a live Art-Net source (any port) has this IPv4 address (host order).
  bool hasArtNetSender(uint32_t ipv4) const;
  // Bumped whenever any merged buffer may have changed: cheap "redecode?" test for pollers.
  uint64_t generation() const { return generation_; }

 private:
  struct Source {
    std::string name;
    int priority = 100;
    std::optional<uint8_t> lastSequence;
    double lastSeenS = 0.0;
    double timeoutS = 2.5;
    bool hasLevels = false;  // a source that has sent only priorities takes no part yet
    DmxBuffer slots{};
    std::optional<DmxBuffer> slotPriority;  // from 0xDD packets; dropped after the timeout
    double slotPriorityAtS = 0.0;
    int slotPriorityAt(size_t i) const;
  };
  struct Universe {
    std::map<DmxSourceId, Source> sources;
    std::optional<DmxBuffer> merged;
  };
  void remerge(Universe& u);
  static std::vector<int> topPriorities(const Universe& u);  // per slot, -1 where none drives it

  MergeOptions options_;
  std::map<int, Universe> universes_;
  uint64_t generation_ = 0;
};

// The E1.31 6.7.2 rule, shared by both protocols: is `next` late relative to `last`?
bool isLateSequence(uint8_t last, uint8_t next);

}  // namespace haze
