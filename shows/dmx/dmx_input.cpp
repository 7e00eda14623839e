// DMX input: parse, count, merge, decode. Counters are data (per-reason maps) so tests and the
// CLI can report exactly why packets were dropped.
#include "shows/dmx/dmx_input.h"
#include "shows/dmx/dmx_reach.h"

#include <algorithm>
#include <cmath>

#include "fixtures/dmx_decode.h"

namespace haze {

uint64_t DmxInputStats::malformedTotal() const {
  uint64_t n = 0;
  for (const auto& [reason, count] : malformed) n += count;
  return n;
}

std::set<int> patchedUniverses(const Show& show) {
  std::set<int> out;
  for (const FixtureDef& f : show.fixtures) {
    if (f.patch) out.insert(f.patch->universe);
  }
  return out;
}

StageState decodeStage(const Show& show, const ProfileSet& profiles,
                       const std::function<const DmxBuffer*(int)>& universeLevels) {
  StageState state;
  for (const FixtureDef& f : show.fixtures) {
    Attributes& a = state[f.id];
    if (!f.patch || f.patch->address < 1 || f.patch->address > 512) continue;
    const DmxMode* mode = dmxModeOf(f, profiles);
    if (!mode) continue;
    const Profile& profile = *profiles.at(f.profile);
    const DmxBuffer* levels = universeLevels(f.patch->universe);
    if (!levels) continue;
    const size_t start = static_cast<size_t>(f.patch->address - 1);
    const size_t count = std::min(static_cast<size_t>(mode->footprint()), levels->size() - start);
    a = decodeDmx(profile, *mode, std::span<const uint8_t>(levels->data() + start, count));
  }
  return state;
}

DmxInput::DmxInput(const Show& show, const ProfileSet& profiles, DmxInputOptions options)
    : show_(show), profiles_(profiles), options_(std::move(options)),
      merger_([&] {
        MergeOptions m = options_.merge;
        if (m.universes.empty()) m.universes = patchedUniverses(show);
        return m;
      }()),
      sync_(options_.sync) {
  state_ = decodeStage(show_, profiles_, [](int) -> const DmxBuffer* { return nullptr; });
}

void DmxInput::countGood(double nowS) {
  ++stats_.good;
  const auto tick = static_cast<int64_t>(std::floor(nowS * 10.0));
  if (tick != rateBucketTick_) {
    // Clear the buckets skipped since the last packet (all of them after a long gap).
    for (int64_t t = rateBucketTick_ + 1; t <= tick && t <= rateBucketTick_ + 10; ++t) {
      rateBuckets_[static_cast<size_t>(((t % 10) + 10) % 10)] = 0;
    }
    rateBucketTick_ = tick;
  }
  ++rateBuckets_[static_cast<size_t>(((tick % 10) + 10) % 10)];
}

double DmxInput::packetRate(double nowS) const {
  const auto tick = static_cast<int64_t>(std::floor(nowS * 10.0));
  if (tick - rateBucketTick_ >= 10) return 0.0;
  uint64_t sum = 0;
  // Buckets older than a second before now are stale.
  for (int64_t t = tick - 9; t <= rateBucketTick_; ++t) {
    sum += rateBuckets_[static_cast<size_t>(((t % 10) + 10) % 10)];
  }
  return static_cast<double>(sum);
}

void DmxInput::countMalformed(const std::string& reason, Error error, const char* protocol,
                              uint32_t ip, uint16_t port) {
  ++stats_.malformed[reason];
  if (stats_.firstMalformed.size() >= DmxInputStats::kKeptMalformed) return;
  error.file = std::string(protocol) + " from " + DmxSourceId::artNet(ip, port).str();
  stats_.firstMalformed.push_back(std::move(error));
}

void DmxInput::submit(const DmxFrame& frame, double nowS) {
  switch (merger_.submit(frame, nowS)) {
    case MergeVerdict::Accepted: countGood(nowS); break;
    case MergeVerdict::LateSequence: ++stats_.late; break;
    case MergeVerdict::Terminated: ++stats_.terminated; break;
    case MergeVerdict::UnwatchedUniverse:
      ++stats_.unwatched;
      if (stats_.unwatchedUniverses.size() < DmxInputStats::kMaxUnwatchedNamed)
        stats_.unwatchedUniverses.insert(frame.universe);
      break;
    case MergeVerdict::SourcesExceeded: ++stats_.exceeded; break;
  }
}

void DmxInput::offer(const SyncGroup& group, const DmxFrame& frame, bool forceSync, double nowS) {
  // Unwatched universes are refused before holding, so they cannot fill the holder.
  if (!options_.synchronise || !merger_.watches(frame.universe)) return submit(frame, nowS);
  switch (sync_.offer(group, frame, forceSync, nowS)) {
    case SyncGate::Verdict::ApplyNow: submit(frame, nowS); break;
    case SyncGate::Verdict::Held: ++stats_.held; break;
    case SyncGate::Verdict::Replaced: ++stats_.held; ++stats_.superseded; break;
    case SyncGate::Verdict::Late: ++stats_.late; break;
    case SyncGate::Verdict::Full: ++stats_.exceeded; break;
  }
}

void DmxInput::release(std::vector<HeldFrame> frames, double nowS) {
  for (const HeldFrame& f : frames) submit(f.view(), nowS);
}

void DmxInput::receiveSacnExtended(std::span<const uint8_t> datagram, uint32_t ip, uint16_t port,
                                   double nowS) {
  const SacnExtendedParse p = parseSacnExtended(datagram);
  if (!p.ok()) {
    countMalformed("sacn." + std::string(sacnStatusName(p.status)), sacnError(p.status, p.byte), "sACN", ip,
                   port);
    return;
  }
  if (p.isSync) {
    ++stats_.syncPackets;
    if (options_.synchronise) release(sync_.sync({DmxProtocol::Sacn, p.sync.syncAddress}, nowS), nowS);
    return;
  }
  const SacnDiscoveryPacket& d = p.discovery;
  auto it = discovered_.find(d.cid);
  if (it == discovered_.end()) {
    if (discovered_.size() >= kMaxDiscoveredSources) {
      ++stats_.exceeded;
      return;
    }
    it = discovered_.emplace(d.cid, DiscoveryPages{}).first;
  }
  ++stats_.discoveryPackets;
  DiscoveryPages& e = it->second;
  // A new last page means the source's list changed size: its old pages no longer apply.
  if (e.source.lastPage != d.lastPage) e.pages.clear();
  e.source.cid = d.cid;
  e.source.name = d.sourceName;
  e.source.lastPage = d.lastPage;
  e.source.lastSeenS = nowS;
  e.pages[d.page] = d.universes;
  e.source.universes.clear();
  for (const auto& [page, list] : e.pages) e.source.universes.insert(list.begin(), list.end());
  e.source.pages = static_cast<int>(e.pages.size());
}

std::vector<ArtTimeCodePacket> DmxInput::takeTimecodes() {
  std::vector<ArtTimeCodePacket> out;
  out.swap(timecodes_);
  return out;
}

std::set<int> DmxInput::dmxFixtures() const {
  std::set<int> out;
  for (const FixtureDef& f : show_.fixtures)
    if (f.patch && merger_.universe(f.patch->universe)) out.insert(f.id);
  return out;
}

std::vector<DiscoveredSource> DmxInput::discovered() const {
  std::vector<DiscoveredSource> out;
  for (const auto& [cid, e] : discovered_) out.push_back(e.source);
  return out;
}

void DmxInput::receive(DmxProtocol protocol, std::span<const uint8_t> datagram,
                       uint32_t senderIpv4, uint16_t senderPort, double nowS) {
  ++stats_.received;
  DmxFrame frame;
  if (protocol == DmxProtocol::ArtNet) {
    if (isArtSync(datagram)) {
      ++stats_.syncPackets;
      if (!options_.synchronise) return;
      // Art-Net 4: an ArtSync counts only for the controller sending the ArtDmx (same IP).
      if (!merger_.hasArtNetSender(senderIpv4)) {
        ++stats_.foreignArtSyncs;
        return;
      }
      release(sync_.sync({DmxProtocol::ArtNet, 0, senderIpv4}, nowS), nowS);
      return;
    }
    if (const ArtTimeCodeParse tc = parseArtTimeCode(datagram); tc.status != ArtTimeCodeStatus::NotTimeCode) {
      if (!tc.ok()) {
        countMalformed("artnet." + std::string(artTimeCodeStatusName(tc.status)),
                       Error{"", "byte " + std::to_string(tc.byte),
                             "ArtTimeCode out of range: expected hours 0..23, minutes and seconds 0..59, frames "
                             "below the rate, type 0..3 and 19 bytes"},
                       "Art-Net", senderIpv4, senderPort);
      } else if (timecodes_.size() >= kMaxPendingTimecodes) {
        ++stats_.exceeded;
      } else {
        ++stats_.timecodePackets;
        timecodes_.push_back(tc.packet);
      }
      return;
    }
    const ArtDmxParse p = parseArtDmx(datagram);
    if (p.status == ArtNetStatus::Ignored) {
      ++stats_.ignored;
      return;
    }
    if (!p.ok()) {
      countMalformed("artnet." + std::string(artNetStatusName(p.status)), artNetError(p), "Art-Net",
                     senderIpv4, senderPort);
      return;
    }
    frame.source = DmxSourceId::artNet(senderIpv4, senderPort);
    frame.universe = p.packet.hazeUniverse();
    frame.priority = 100;
    if (p.packet.sequence != 0) frame.sequence = p.packet.sequence;
    frame.slots = std::span<const uint8_t>(p.packet.slots.data(),
                                           static_cast<size_t>(p.packet.length));
    offer({DmxProtocol::ArtNet, 0, senderIpv4}, frame, false, nowS);
    return;
  }
  const SacnParse p = parseSacn(datagram);
  if (p.status == SacnStatus::Ignored && p.byte == 18) {
    receiveSacnExtended(datagram, senderIpv4, senderPort, nowS);
    return;
  }
  if (p.status == SacnStatus::Ignored) {
    ++stats_.ignored;
    return;
  }
  if (!p.ok()) {
    countMalformed("sacn." + std::string(sacnStatusName(p.status)), sacnError(p), "sACN",
                   senderIpv4, senderPort);
    return;
  }
  if (p.packet.preview() && !options_.acceptPreview) {
    ++stats_.ignored;
    return;
  }
  frame.source = DmxSourceId::sacn(p.packet.cid);
  frame.name = p.packet.sourceName;
  frame.universe = p.packet.universe;
  frame.priority = p.packet.priority;
  frame.sequence = p.packet.sequence;
  frame.terminated = p.packet.terminated();
  frame.perSlotPriority = p.packet.startCode == kSacnStartPerSlotPriority;
  frame.slots = std::span<const uint8_t>(p.packet.slots.data(),
                                         static_cast<size_t>(p.packet.slotCount));
  // Stream_Terminated takes effect at once: the source leaves the universe, whatever it
  // synchronises on, and what it had waiting there for a sync packet goes with it.
  if (frame.terminated) stats_.superseded += sync_.forget(frame.source, frame.universe);
  if (p.packet.syncAddress != 0 && !frame.terminated)
    offer({DmxProtocol::Sacn, p.packet.syncAddress}, frame, p.packet.forceSync(), nowS);
  else
    submit(frame, nowS);
}

const StageState& DmxInput::poll(double nowS) {
  release(sync_.expire(nowS), nowS);
  merger_.expire(nowS);
  std::erase_if(discovered_, [&](const auto& kv) { return nowS - kv.second.source.lastSeenS > kDiscoveryForgetS; });
  if (merger_.generation() != decodedGeneration_) {
    state_ = decodeStage(show_, profiles_, [&](int u) { return merger_.universe(u); });
    for (const FixtureDef& f : show_.fixtures)
      if (f.patch && merger_.blackedOut(f.patch->universe)) state_[f.id].intensity = 0.0f;
    decodedGeneration_ = merger_.generation();
  }
  return state_;
}

}  // namespace haze
