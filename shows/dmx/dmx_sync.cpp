// Sync groups: hold, release on sync, fall back on timeout (see dmx_sync.h).
#include "shows/dmx/dmx_sync.h"

#include <algorithm>

namespace haze {

SyncGate::SyncGate(SyncOptions options) : options_(options) {}

void SyncGate::noteAddress(const SyncGroup& g) {
  if (g.protocol != DmxProtocol::Sacn || sacnAddresses_.size() >= options_.maxGroups) return;
  if (std::find(sacnAddresses_.begin(), sacnAddresses_.end(), g.address) == sacnAddresses_.end())
    sacnAddresses_.push_back(g.address);
}

double SyncGate::timeout(const SyncGroup& g) const {
  return g.protocol == DmxProtocol::Sacn ? options_.sacnTimeoutS : options_.artNetTimeoutS;
}

bool SyncGate::synchronised(const SyncGroup& group, double nowS) const {
  auto it = groups_.find(group);
  return it != groups_.end() && it->second.lastSyncS && nowS - *it->second.lastSyncS <= timeout(group);
}

SyncGate::Verdict SyncGate::offer(const SyncGroup& group, const DmxFrame& frame, bool forceSync,
                                  double nowS) {
  noteAddress(group);
  auto it = groups_.find(group);
  if (it == groups_.end()) {
    // A group that never had a sync packet holds nothing, unless the sender forces it.
    if (!forceSync) return Verdict::ApplyNow;
    if (groups_.size() >= options_.maxGroups) return Verdict::Full;
    it = groups_.emplace(group, Group{}).first;
  }
  Group& g = it->second;
  if (group.protocol == DmxProtocol::Sacn) g.forced = forceSync;
  if (!synchronised(group, nowS) && !g.forced) return Verdict::ApplyNow;
  const Key key{frame.source, frame.universe, frame.perSlotPriority};
  auto h = g.held.find(key);
  const bool replacing = h != g.held.end();
  if (!replacing) {
    if (heldCount_ >= options_.maxHeld) return Verdict::Full;
    h = g.held.emplace(key, std::pair<uint64_t, HeldFrame>{}).first;
    ++heldCount_;
  } else if (frame.sequence && h->second.second.frame.sequence &&
             isLateSequence(*h->second.second.frame.sequence, *frame.sequence)) {
    return Verdict::Late;
  }
  HeldFrame& held = h->second.second;
  h->second.first = arrivals_++;
  held.frame = frame;
  held.frame.slots = {};
  held.count = std::min(frame.slots.size(), held.data.size());
  std::copy_n(frame.slots.begin(), held.count, held.data.begin());
  return replacing ? Verdict::Replaced : Verdict::Held;
}

std::vector<HeldFrame> SyncGate::take(Group& g) {
  std::vector<std::pair<uint64_t, HeldFrame>> all;
  all.reserve(g.held.size());
  for (auto& [key, entry] : g.held) all.push_back(std::move(entry));
  heldCount_ -= g.held.size();
  g.held.clear();
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<HeldFrame> out;
  out.reserve(all.size());
  for (auto& [n, f] : all) out.push_back(std::move(f));
  return out;
}

std::vector<HeldFrame> SyncGate::sync(const SyncGroup& group, double nowS) {
  auto it = groups_.find(group);
  if (it == groups_.end()) {
    if (groups_.size() >= options_.maxGroups) return {};
    it = groups_.emplace(group, Group{}).first;
  }
  it->second.lastSyncS = nowS;
  return take(it->second);
}

size_t SyncGate::forget(const DmxSourceId& source, int universe) {
  size_t n = 0;
  for (auto& [group, g] : groups_)
    n += std::erase_if(g.held, [&](const auto& kv) {
      return std::get<0>(kv.first) == source && std::get<1>(kv.first) == universe;
    });
  heldCount_ -= n;
  return n;
}

std::vector<HeldFrame> SyncGate::expire(double nowS) {
  std::vector<HeldFrame> out;
  for (auto& [group, g] : groups_) {
    if (g.held.empty() || g.forced || synchronised(group, nowS)) continue;
    for (HeldFrame& f : take(g)) out.push_back(std::move(f));
  }
  return out;
}

}  // namespace haze
