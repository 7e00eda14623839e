// DMX merge: priority per slot, HTP among the top priority, timeouts, sequence discard.
// Each universe is re-merged from its sources' last levels whenever one of them changes; a
// universe has at most a handful of sources, so this is a few thousand byte compares.
#include "shows/dmx/dmx_merge.h"

#include <algorithm>
#include <cstdio>

namespace haze {

DmxSourceId DmxSourceId::sacn(const std::array<uint8_t, 16>& cid) {
  DmxSourceId id;
  id.protocol = DmxProtocol::Sacn;
  id.bytes = cid;
  return id;
}

DmxSourceId DmxSourceId::artNet(uint32_t ip, uint16_t port) {
  DmxSourceId id;
  id.protocol = DmxProtocol::ArtNet;
  id.bytes[0] = static_cast<uint8_t>(ip >> 24);
  id.bytes[1] = static_cast<uint8_t>(ip >> 16);
  id.bytes[2] = static_cast<uint8_t>(ip >> 8);
  id.bytes[3] = static_cast<uint8_t>(ip);
  id.bytes[4] = static_cast<uint8_t>(port >> 8);
  id.bytes[5] = static_cast<uint8_t>(port);
  return id;
}

std::string DmxSourceId::str() const {
  char s[48];
  const auto& b = bytes;
  if (protocol == DmxProtocol::ArtNet) {
    std::snprintf(s, sizeof s, "%d.%d.%d.%d:%d", b[0], b[1], b[2], b[3], (b[4] << 8) | b[5]);
  } else {
    std::snprintf(s, sizeof s,
                  "%02x%02x%02x%02x-%02x%02x-%02x%02x-%02x%02x-%02x%02x%02x%02x%02x%02x", b[0],
                  b[1], b[2], b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10], b[11], b[12], b[13],
                  b[14], b[15]);
  }
  return s;
}

bool isLateSequence(uint8_t last, uint8_t next) {
  // Signed 8-bit difference, so 255 -> 0 is +1 and not -255.
  const int diff = static_cast<int8_t>(static_cast<uint8_t>(next - last));
  return diff <= 0 && diff > -20;
}

DmxMerger::DmxMerger(MergeOptions options) : options_(std::move(options)) {}

bool DmxMerger::watches(int universe) const {
  return options_.universes.empty() || options_.universes.count(universe);
}

// Without per-slot priorities every slot has the universe priority; 0 there still drives the
// slot (as priority 1), since a per-slot 0 is reserved for "not driven".
int DmxMerger::Source::slotPriorityAt(size_t i) const {
  return slotPriority ? (*slotPriority)[i] : std::max(priority, 1);
}

MergeVerdict DmxMerger::submit(const DmxFrame& f, double nowS) {
  if (!watches(f.universe)) return MergeVerdict::UnwatchedUniverse;
  auto uit = universes_.find(f.universe);
  if (uit == universes_.end()) {
    if (f.terminated) return MergeVerdict::Terminated;
    if (static_cast<int>(universes_.size()) >= options_.maxUniverses) {
      return MergeVerdict::SourcesExceeded;
    }
    uit = universes_.emplace(f.universe, Universe{}).first;
  }
  Universe& u = uit->second;
  auto sit = u.sources.find(f.source);
  if (f.terminated) {
    // E1.31 6.2.6: the source enters data loss at once and its levels are ignored.
    if (sit != u.sources.end()) {
      u.sources.erase(sit);
      remerge(u);
    }
    return MergeVerdict::Terminated;
  }
  if (sit == u.sources.end()) {
    if (static_cast<int>(u.sources.size()) >= options_.maxSourcesPerUniverse) {
      return MergeVerdict::SourcesExceeded;
    }
    sit = u.sources.emplace(f.source, Source{}).first;
  } else if (f.sequence && sit->second.lastSequence &&
             isLateSequence(*sit->second.lastSequence, *f.sequence)) {
    return MergeVerdict::LateSequence;
  }
  Source& s = sit->second;
  s.name = f.name;
  s.priority = std::clamp(f.priority, 0, 200);
  s.lastSequence = f.sequence;
  s.lastSeenS = nowS;
  s.timeoutS = f.source.protocol == DmxProtocol::Sacn ? options_.sacnTimeoutS
                                                      : options_.artNetTimeoutS;
  // Slots a packet leaves out are 0: levels off, or priorities "not driven".
  DmxBuffer& into = f.perSlotPriority ? s.slotPriority.emplace() : s.slots;
  const size_t n = std::min<size_t>(f.slots.size(), into.size());
  std::copy_n(f.slots.begin(), n, into.begin());
  std::fill(into.begin() + static_cast<long>(n), into.end(), uint8_t{0});
  if (f.perSlotPriority) {
    for (uint8_t& p : into) p = std::min<uint8_t>(p, 200);
    s.slotPriorityAtS = nowS;
  } else {
    s.hasLevels = true;
  }
  remerge(u);
  return MergeVerdict::Accepted;
}

int DmxMerger::expire(double nowS) {
  int dropped = 0;
  for (auto& [number, u] : universes_) {
    const size_t before = u.sources.size();
    std::erase_if(u.sources, [&](const auto& kv) {
      return nowS - kv.second.lastSeenS > kv.second.timeoutS;
    });
    bool changed = u.sources.size() != before;
    dropped += static_cast<int>(before - u.sources.size());
    // A source that stops sending 0xDD but keeps sending levels falls back to its universe
    // priority after the same loss timeout.
    for (auto& [id, s] : u.sources) {
      if (s.slotPriority && nowS - s.slotPriorityAtS > s.timeoutS) {
        s.slotPriority.reset();
        changed = true;
      }
    }
    if (changed) remerge(u);
  }
  return dropped;
}

std::vector<int> DmxMerger::topPriorities(const Universe& u) {
  std::vector<int> top(512, -1);
  for (const auto& [id, s] : u.sources) {
    if (!s.hasLevels) continue;
    for (size_t i = 0; i < top.size(); ++i) {
      const int p = s.slotPriorityAt(i);
      if (p > 0) top[i] = std::max(top[i], p);
    }
  }
  return top;
}

void DmxMerger::remerge(Universe& u) {
  ++generation_;
  const bool anyLevels = std::any_of(u.sources.begin(), u.sources.end(),
                                     [](const auto& kv) { return kv.second.hasLevels; });
  if (!anyLevels) return;  // the last levels stay, under either loss policy
  const std::vector<int> top = topPriorities(u);
  DmxBuffer merged{};  // a slot no source drives is 0
  for (const auto& [id, s] : u.sources) {
    if (!s.hasLevels) continue;
    for (size_t i = 0; i < merged.size(); ++i)
      if (s.slotPriorityAt(i) == top[i]) merged[i] = std::max(merged[i], s.slots[i]);
  }
  u.merged = merged;
}

const DmxBuffer* DmxMerger::universe(int number) const {
  auto it = universes_.find(number);
  if (it == universes_.end() || !it->second.merged) return nullptr;
  return &*it->second.merged;
}

bool DmxMerger::blackedOut(int number) const {
  auto it = universes_.find(number);
  // Had data, has no source left: lost (a universe that never had data is not "lost").
  return options_.onLoss == LossPolicy::Blackout && it != universes_.end() && it->second.sources.empty() &&
         it->second.merged.has_value();
}

std::vector<int> DmxMerger::activeUniverses() const {
  std::vector<int> out;
  for (const auto& [number, u] : universes_) {
    if (!u.sources.empty()) out.push_back(number);
  }
  return out;
}

std::vector<DmxSourceInfo> DmxMerger::sources() const {
  std::vector<DmxSourceInfo> out;
  for (const auto& [number, u] : universes_) {
    const std::vector<int> top = topPriorities(u);
    for (const auto& [id, s] : u.sources) {
      bool winning = false;
      for (size_t i = 0; i < top.size() && s.hasLevels && !winning; ++i)
        winning = top[i] > 0 && s.slotPriorityAt(i) == top[i];
      out.push_back({id, s.name, number, s.priority, winning, s.slotPriority.has_value(), s.lastSeenS});
    }
  }
  return out;
}

}  // namespace haze

namespace haze {

bool DmxMerger::hasArtNetSender(uint32_t ipv4) const {
  const DmxSourceId probe = DmxSourceId::artNet(ipv4, 0);
  for (const auto& [number, u] : universes_)
    for (const auto& [id, source] : u.sources)
      if (id.protocol == DmxProtocol::ArtNet && std::equal(id.bytes.begin(), id.bytes.begin() + 4, probe.bytes.begin()))
        return true;
  return false;
}

}  // namespace haze
