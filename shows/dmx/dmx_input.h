// DMX input without sockets: datagrams in (Art-Net or sACN bytes, the sender's address and the
// time), a StageState out, decoded through each fixture's patch and mode. The socket side
// (shows/dmx/udp_receiver.h) and tests feed it; the GUI polls it every frame for the state, the active
// sources and the packet rates.
//
// Universes: haze universes count from 1. sACN universe N is haze universe N; Art-Net
// Port-Address P (Net:Sub-Net:Universe) is haze universe P + 1, so Art-Net 0:0:0 is universe 1.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "shows/dmx/artnet.h"
#include "shows/dmx/artnet_timecode.h"
#include "shows/dmx/dmx_merge.h"
#include "shows/dmx/dmx_sync.h"
#include "shows/playback.h"
#include "shows/dmx/sacn.h"
#include "shows/show.h"

namespace haze {

// Every fixture of the show with its attributes from the universes (defaults for a fixture
// without a patch, without a usable profile or mode, or on a universe with no data).
StageState decodeStage(const Show& show, const ProfileSet& profiles,
                       const std::function<const DmxBuffer*(int universe)>& universeLevels);

// The universes the show's patched fixtures listen to.
std::set<int> patchedUniverses(const Show& show);

struct DmxInputStats {
  uint64_t received = 0;     // datagrams handed in
  uint64_t good = 0;         // accepted into the merge
  uint64_t ignored = 0;      // valid but not levels: other opcodes, sync, alternate START codes
  uint64_t late = 0;         // discarded by the sequence rule
  uint64_t terminated = 0;   // sACN Stream_Terminated packets
  uint64_t unwatched = 0;    // levels for a universe no fixture is patched on
  std::set<int> unwatchedUniverses;  // which (the first kMaxUnwatchedNamed), for the warning
  static constexpr size_t kMaxUnwatchedNamed = 64;
  uint64_t exceeded = 0;     // sources beyond the merger's (or the sync holder's) limits
  uint64_t syncPackets = 0;  // ArtSync and E1.31 synchronization packets
  uint64_t foreignArtSyncs = 0;  // of syncPackets: ArtSync from an address that sends no ArtDmx
  // Every datagram ends in exactly one of the counts above and below, except held frames: `held`
  // counts them as they are held, and each is counted again when its sync releases it (good,
  // late...) or as superseded; SyncGate::heldCount() are those still waiting.
  uint64_t held = 0;         // frames held for a sync packet
  uint64_t superseded = 0;   // held frames replaced by a newer one before their sync came (or
                             // dropped because their source sent Stream_Terminated)
  uint64_t discoveryPackets = 0;  // E1.31 universe discovery pages
  uint64_t timecodePackets = 0;   // ArtTimeCode (kept for takeTimecodes)
  std::map<std::string, uint64_t> malformed;  // "sacn.bad_priority" -> count
  // The first few malformed packets in full (file = protocol and sender), for the log.
  std::vector<Error> firstMalformed;
  static constexpr size_t kKeptMalformed = 8;
  uint64_t malformedTotal() const;
};

struct DmxInputOptions {
  MergeOptions merge;         // merge.universes is filled from the show when left empty
  SyncOptions sync;
  bool acceptPreview = true;  // sACN Preview_Data is meant for visualisers: haze is one
  bool synchronise = true;    // honour ArtSync and E1.31 synchronization
};

// An sACN source as its universe discovery packets describe it.
struct DiscoveredSource {
  std::array<uint8_t, 16> cid{};
  std::string name;
  std::set<int> universes;  // the pages received so far, together
  int pages = 0;            // of lastPage + 1
  int lastPage = 0;
  double lastSeenS = 0.0;
  std::string cidString() const { return DmxSourceId::sacn(cid).str(); }
};
inline constexpr size_t kMaxDiscoveredSources = 64;
inline constexpr double kDiscoveryForgetS = 30.0;  // three E131_UNIVERSE_DISCOVERY_INTERVALs

class DmxInput {
 public:
  // show and profiles are referenced, not copied: they must outlive the DmxInput.
  DmxInput(const Show& show, const ProfileSet& profiles, DmxInputOptions options = {});

  // One datagram. senderIpv4 is in host byte order (Art-Net sources are told apart by it).
  void receive(DmxProtocol protocol, std::span<const uint8_t> datagram, uint32_t senderIpv4,
               uint16_t senderPort, double nowS);
  // Expires silent sources and returns the current state (re-decoded only when levels changed).
  const StageState& poll(double nowS);

  const StageState& state() const { return state_; }
  std::vector<DmxSourceInfo> sources() const { return merger_.sources(); }
  const DmxInputStats& stats() const { return stats_; }
  const DmxMerger& merger() const { return merger_; }
  const SyncGate& syncGate() const { return sync_; }
  // The ArtTimeCode readings since the last call, oldest first (at most kMaxPendingTimecodes;
  // more between two calls are counted as exceeded).
  std::vector<ArtTimeCodePacket> takeTimecodes();
  static constexpr size_t kMaxPendingTimecodes = 1024;
  // The fixtures whose universe has DMX levels (live, or held after a loss).
  std::set<int> dmxFixtures() const;
  // sACN sources heard through universe discovery (universe 64214), by CID; forgotten 30 s after
  // their last page.
  std::vector<DiscoveredSource> discovered() const;
  // Good packets per second over the last second before nowS.
  double packetRate(double nowS) const;

 private:
  void countGood(double nowS);
  void submit(const DmxFrame& frame, double nowS);
  void offer(const SyncGroup& group, const DmxFrame& frame, bool forceSync, double nowS);
  void release(std::vector<HeldFrame> frames, double nowS);
  void receiveSacnExtended(std::span<const uint8_t> datagram, uint32_t ip, uint16_t port, double nowS);
  void countMalformed(const std::string& reason, Error error, const char* protocol,
                      uint32_t senderIpv4, uint16_t senderPort);

  const Show& show_;
  const ProfileSet& profiles_;
  DmxInputOptions options_;
  DmxMerger merger_;
  SyncGate sync_;
  struct DiscoveryPages {
    DiscoveredSource source;
    std::map<int, std::vector<uint16_t>> pages;
  };
  std::map<std::array<uint8_t, 16>, DiscoveryPages> discovered_;
  DmxInputStats stats_;
  std::vector<ArtTimeCodePacket> timecodes_;
  StageState state_;
  uint64_t decodedGeneration_ = ~uint64_t{0};
  // Good-packet counts in 100 ms buckets, for the rate.
  std::array<uint64_t, 10> rateBuckets_{};
  int64_t rateBucketTick_ = 0;
};

}  // namespace haze
