// Not a timed test: disabled by default, it only prints how many full sACN packets per second
// DmxInput takes (parse + merge, a decode every 44 packets as a frame loop would). Run with
//   unit_live --gtest_also_run_disabled_tests --gtest_filter='*Throughput*'
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "shows/dmx_input.h"
#include "unit/live/packets.h"
#include "unit/live/test_show.h"

namespace haze {
namespace {

TEST(DmxInputThroughput, DISABLED_FullSacnPackets) {
  const test::TestShow t = test::makeTestShow();
  DmxInput input(t.show, t.profiles);
  test::SacnFields f;
  std::vector<std::vector<uint8_t>> packets;
  for (int i = 0; i < 256; ++i) {
    f.sequence = static_cast<uint8_t>(i);
    f.slots[0] = static_cast<uint8_t>(i);
    packets.push_back(test::sacn(f));
  }
  const int n = 400000;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    input.receive(DmxProtocol::Sacn, packets[static_cast<size_t>(i % 256)], 0x7F000001, 1, i * 1e-5);
    if (i % 44 == 0) input.poll(i * 1e-5);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("DmxInput: %d full sACN packets in %.3f s = %.0f packets/s\n", n, s, n / s);
  EXPECT_EQ(input.stats().good, static_cast<uint64_t>(n));
}

}  // namespace
}  // namespace haze
