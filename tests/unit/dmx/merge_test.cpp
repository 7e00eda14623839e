// Merge rules with an injected clock: highest priority wins, HTP among equal top priorities,
// 2.5 s sACN data-loss timeout (10 s for Art-Net), Stream_Terminated, E1.31 sequence discard.
#include <gtest/gtest.h>

#include "shows/dmx/dmx_merge.h"

namespace haze {
namespace {

DmxSourceId cid(uint8_t n) {
  std::array<uint8_t, 16> c{};
  c.fill(n);
  return DmxSourceId::sacn(c);
}

struct Sender {
  DmxSourceId id;
  int priority = 100;
  std::vector<uint8_t> slots;
  uint8_t sequence = 0;

  DmxFrame frame(int universe = 1) {
    DmxFrame f;
    f.source = id;
    f.universe = universe;
    f.priority = priority;
    f.sequence = sequence++;
    f.slots = slots;
    return f;
  }
};

TEST(Merge, HighestPriorityWins) {
  DmxMerger m;
  Sender a{cid(1), 100, {200, 200}};
  Sender b{cid(2), 150, {50}};
  EXPECT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 200);
  EXPECT_EQ(m.submit(b.frame(), 0.1), MergeVerdict::Accepted);
  // B's 50 wins over A's 200, and B's missing slot 2 is 0, not A's 200.
  EXPECT_EQ((*m.universe(1))[0], 50);
  EXPECT_EQ((*m.universe(1))[1], 0);
  const auto sources = m.sources();
  ASSERT_EQ(sources.size(), 2u);
  for (const auto& s : sources) EXPECT_EQ(s.winning, s.priority == 150) << s.id.str();
}

TEST(Merge, HtpAmongEqualTopPriority) {
  DmxMerger m;
  Sender a{cid(1), 100, {10, 200, 0}};
  Sender b{cid(2), 100, {100, 20, 0}};
  Sender low{cid(3), 99, {255, 255, 255}};
  ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
  ASSERT_EQ(m.submit(b.frame(), 0.0), MergeVerdict::Accepted);
  ASSERT_EQ(m.submit(low.frame(), 0.0), MergeVerdict::Accepted);
  const DmxBuffer& u = *m.universe(1);
  EXPECT_EQ(u[0], 100);
  EXPECT_EQ(u[1], 200);
  EXPECT_EQ(u[2], 0);
}

TEST(Merge, SacnSourceTimesOutAfter2point5Seconds) {
  DmxMerger m;
  Sender high{cid(1), 200, {10}};
  Sender low{cid(2), 100, {90}};
  ASSERT_EQ(m.submit(high.frame(), 0.0), MergeVerdict::Accepted);
  ASSERT_EQ(m.submit(low.frame(), 1.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 10);
  EXPECT_EQ(m.expire(2.4), 0);
  EXPECT_EQ((*m.universe(1))[0], 10);
  EXPECT_EQ(m.expire(2.6), 1);  // high: silent 2.6 s
  EXPECT_EQ((*m.universe(1))[0], 90);
  EXPECT_EQ(m.sources().size(), 1u);
  EXPECT_EQ(m.expire(3.4), 0);  // low: silent 2.4 s
  EXPECT_EQ(m.expire(3.6), 1);
  EXPECT_TRUE(m.sources().empty());
  EXPECT_TRUE(m.activeUniverses().empty());
}

TEST(Merge, LossHoldsLastLookOrBlacksOut) {
  {
    DmxMerger m;
    Sender a{cid(1), 100, {77}};
    ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
    m.expire(3.0);
    ASSERT_NE(m.universe(1), nullptr);
    EXPECT_EQ((*m.universe(1))[0], 77);
  }
  {
    MergeOptions o;
    o.onLoss = LossPolicy::Blackout;
    DmxMerger m(o);
    Sender a{cid(1), 100, {77}};
    ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
    EXPECT_FALSE(m.blackedOut(1));
    m.expire(3.0);
    EXPECT_TRUE(m.blackedOut(1));
    ASSERT_NE(m.universe(1), nullptr) << "the last levels stay, so heads hold where they were";
    EXPECT_EQ((*m.universe(1))[0], 77);
    ASSERT_EQ(m.submit(a.frame(), 4.0), MergeVerdict::Accepted);
    EXPECT_FALSE(m.blackedOut(1)) << "a source coming back lights the universe again";
  }
}

TEST(Merge, ArtNetSourcesTimeOutAfterTenSeconds) {
  DmxMerger m;
  DmxFrame f;
  f.source = DmxSourceId::artNet(0x7F000001, 6454);
  const std::vector<uint8_t> slots = {42, 43};
  f.slots = slots;
  ASSERT_EQ(m.submit(f, 0.0), MergeVerdict::Accepted);
  EXPECT_EQ(m.expire(9.9), 0);
  EXPECT_EQ(m.expire(10.1), 1);
  EXPECT_EQ(f.source.str(), "127.0.0.1:6454");
}

TEST(Merge, SequenceRuleOfE131) {
  // Late when (new - last) is in (-20, 0], computed in 8-bit two's complement.
  EXPECT_TRUE(isLateSequence(10, 10));
  EXPECT_TRUE(isLateSequence(10, 9));
  EXPECT_TRUE(isLateSequence(10, 247));   // -19
  EXPECT_FALSE(isLateSequence(10, 246));  // -20: taken as a restart
  EXPECT_FALSE(isLateSequence(10, 11));
  EXPECT_FALSE(isLateSequence(255, 0));   // wrap: +1
  EXPECT_TRUE(isLateSequence(5, 250));    // -11 across the wrap
  EXPECT_FALSE(isLateSequence(10, 138));  // +128 reads as -128: not late
}

TEST(Merge, LatePacketsAreDiscarded) {
  DmxMerger m;
  Sender a{cid(1), 100, {100}};
  a.sequence = 50;
  ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);  // seq 50
  a.slots = {5};
  a.sequence = 45;
  EXPECT_EQ(m.submit(a.frame(), 0.1), MergeVerdict::LateSequence);
  EXPECT_EQ((*m.universe(1))[0], 100);
  a.sequence = 50;  // a duplicate is late too
  EXPECT_EQ(m.submit(a.frame(), 0.1), MergeVerdict::LateSequence);
  a.sequence = 51;
  EXPECT_EQ(m.submit(a.frame(), 0.2), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 5);
  // Sequences are per source: another source's numbers do not interfere.
  Sender b{cid(2), 100, {7}};
  b.sequence = 0;
  EXPECT_EQ(m.submit(b.frame(), 0.3), MergeVerdict::Accepted);
}

TEST(Merge, ArtNetWithoutSequenceIsNeverLate) {
  DmxMerger m;
  DmxFrame f;
  f.source = DmxSourceId::artNet(0x0A000001, 6454);
  const std::vector<uint8_t> slots = {1};
  f.slots = slots;
  EXPECT_EQ(m.submit(f, 0.0), MergeVerdict::Accepted);
  EXPECT_EQ(m.submit(f, 0.1), MergeVerdict::Accepted);
}

TEST(Merge, StreamTerminatedRemovesTheSourceAtOnce) {
  DmxMerger m;
  Sender a{cid(1), 150, {200}};
  Sender b{cid(2), 100, {30}};
  ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
  ASSERT_EQ(m.submit(b.frame(), 0.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 200);
  DmxFrame bye = a.frame();
  bye.terminated = true;
  const std::vector<uint8_t> ignored = {255};
  bye.slots = ignored;  // levels of a terminating packet are ignored
  EXPECT_EQ(m.submit(bye, 0.1), MergeVerdict::Terminated);
  EXPECT_EQ((*m.universe(1))[0], 30);
  EXPECT_EQ(m.sources().size(), 1u);
  // The usual three terminate packets: the repeats change nothing and create no source.
  EXPECT_EQ(m.submit(bye, 0.1), MergeVerdict::Terminated);
  EXPECT_EQ(m.sources().size(), 1u);
  // A later stream from the same CID starts afresh, sequence history forgotten.
  a.sequence = 0;
  EXPECT_EQ(m.submit(a.frame(), 1.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 200);
}

TEST(Merge, LimitsAndUnwatchedUniverses) {
  MergeOptions o;
  o.universes = {1};
  o.maxSourcesPerUniverse = 3;
  DmxMerger m(o);
  for (uint8_t i = 1; i <= 3; ++i) {
    Sender s{cid(i), 100, {i}};
    EXPECT_EQ(m.submit(s.frame(), 0.0), MergeVerdict::Accepted);
  }
  Sender extra{cid(9), 100, {255}};
  EXPECT_EQ(m.submit(extra.frame(), 0.0), MergeVerdict::SourcesExceeded);
  EXPECT_EQ((*m.universe(1))[0], 3);
  Sender other{cid(1), 100, {1}};
  EXPECT_EQ(m.submit(other.frame(2), 0.0), MergeVerdict::UnwatchedUniverse);
  EXPECT_EQ(m.universe(2), nullptr);
}

TEST(Merge, GenerationMovesWhenLevelsMayChange) {
  DmxMerger m;
  const uint64_t g0 = m.generation();
  Sender a{cid(1), 100, {1}};
  ASSERT_EQ(m.submit(a.frame(), 0.0), MergeVerdict::Accepted);
  const uint64_t g1 = m.generation();
  EXPECT_GT(g1, g0);
  m.expire(1.0);
  EXPECT_EQ(m.generation(), g1);
  m.expire(3.0);
  EXPECT_GT(m.generation(), g1);
}

// Per-slot priority (sACN START code 0xDD): each slot goes to its own top priority, HTP among
// equals; per-slot 0 leaves the slot to the others; a source without 0xDD competes at its
// universe priority on every slot. Expected values worked slot by slot below.
TEST(Merge, PerSlotPriorityMergesChannelByChannel) {
  DmxMerger m;
  Sender main{cid(1), 100, {10, 20, 30, 40}};
  Sender backup{cid(2), 100, {99, 99, 99, 99}};
  EXPECT_EQ(m.submit(main.frame(), 0.0), MergeVerdict::Accepted);
  EXPECT_EQ(m.submit(backup.frame(), 0.0), MergeVerdict::Accepted);
  // Both at 100 everywhere: HTP, backup's 99s win.
  EXPECT_EQ((*m.universe(1))[0], 99);
  // Backup sends per-slot priorities: slot 1 at 150 (wins), slot 2 at 100 (ties: HTP), slot 3
  // at 50 (loses to main's 100), slot 4 at 0 (not driven by backup).
  Sender backupPap{cid(2), 100, {150, 100, 50, 0}};
  backupPap.sequence = backup.sequence;
  DmxFrame pap = backupPap.frame();
  pap.perSlotPriority = true;
  EXPECT_EQ(m.submit(pap, 0.1), MergeVerdict::Accepted);
  const DmxBuffer& u = *m.universe(1);
  EXPECT_EQ(u[0], 99);  // backup alone at 150
  EXPECT_EQ(u[1], 99);  // 100 vs 100: max(20, 99)
  EXPECT_EQ(u[2], 30);  // main's 100 beats 50
  EXPECT_EQ(u[3], 40);  // backup does not drive slot 4
  EXPECT_EQ(u[4], 0);   // slots beyond both: main drives them at 100 with 0
  // Both are winning somewhere.
  for (const DmxSourceInfo& s : m.sources()) EXPECT_TRUE(s.winning) << s.id.str();
  // Per-slot priorities from backup that stop arriving fall back to its universe priority after
  // the loss timeout, while its levels keep coming.
  backup.sequence = backupPap.sequence;
  backup.slots = {1, 1, 1, 1};
  EXPECT_EQ(m.submit(backup.frame(), 2.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 1);  // still 150 on slot 1
  EXPECT_EQ((*m.universe(1))[3], 40);
  main.slots = {10, 20, 30, 40};
  EXPECT_EQ(m.submit(main.frame(), 2.7), MergeVerdict::Accepted);
  EXPECT_EQ(m.submit(backup.frame(), 2.7), MergeVerdict::Accepted);
  m.expire(2.7);  // 0xDD last at 0.1: older than 2.5 s
  EXPECT_EQ((*m.universe(1))[0], 10);  // both at 100 again: HTP
  EXPECT_EQ((*m.universe(1))[3], 40);
}

// A source that has sent only priorities has no levels yet: it does not make its slots 0.
TEST(Merge, PrioritiesWithoutLevelsTakeNoPart) {
  DmxMerger m;
  Sender a{cid(1), 100, {0xDD}};
  DmxFrame pap = a.frame();
  pap.perSlotPriority = true;
  EXPECT_EQ(m.submit(pap, 0.0), MergeVerdict::Accepted);
  EXPECT_EQ(m.universe(1), nullptr);
  Sender b{cid(2), 100, {7}};
  EXPECT_EQ(m.submit(b.frame(), 0.0), MergeVerdict::Accepted);
  EXPECT_EQ((*m.universe(1))[0], 7);
}

}  // namespace
}  // namespace haze
