// The map-work policy with a clock the test controls: each job "takes" a set time; the budget,
// the order (longest-waiting first) and the first job's guarantee are checked on what ran.
#include <gtest/gtest.h>

#include "shows/scene/map_schedule.h"

namespace haze {
namespace {

struct FakeWork {
  double nowMs = 0.0;
  double lightMs = 4.0, shadowMs = 6.0;
  std::vector<MapJob> ran;

  std::function<double()> clock() {
    return [this] { return nowMs; };
  }
  std::function<bool(const MapJob&)> work() {
    return [this](const MapJob& j) {
      nowMs += j.kind == MapKind::Light ? lightMs : shadowMs;
      ran.push_back(j);
      return true;
    };
  }
};

std::vector<int> beams(const std::vector<MapJob>& jobs) {
  std::vector<int> out;
  for (const MapJob& j : jobs) out.push_back(j.beam);
  return out;
}

TEST(MapSchedule, LongestWaitingFirstThenBeamThenLightBeforeShadow) {
  MapSchedule schedule;
  FakeWork w;
  std::vector<MapJob> jobs{{5, 1, MapKind::Shadow}, {3, 7, MapKind::Shadow}, {5, 1, MapKind::Light},
                           {3, 2, MapKind::Light}, {9, 0, MapKind::Light}};
  EXPECT_EQ(schedule.run(jobs, 1000.0, w.clock(), w.work()), 5);
  EXPECT_EQ(beams(w.ran), (std::vector<int>{2, 7, 1, 1, 0}));
  EXPECT_EQ(w.ran[2].kind, MapKind::Light);
  EXPECT_EQ(w.ran[3].kind, MapKind::Shadow);
}

// Before anything is measured the policy cannot predict: the jobs run until the budget is
// spent. Then a job goes only if the last one of its kind would still end within the budget.
TEST(MapSchedule, AJobGoesOnlyWhileTheLastOfItsKindWouldFit) {
  MapSchedule schedule;
  FakeWork w;
  std::vector<MapJob> shadows;
  for (int i = 0; i < 10; ++i) shadows.push_back({1, i, MapKind::Shadow});
  // Nothing measured: 0 + 0 <= 15, 6 + 6 <= 15, 12 + 6 > 15: two run.
  EXPECT_EQ(schedule.run(shadows, 15.0, w.clock(), w.work()), 2);
  EXPECT_DOUBLE_EQ(schedule.lastMs(MapKind::Shadow), 6.0);
  // Next frame: 0 (first goes), 6 + 6 = 12 <= 15 goes, 12 + 6 > 15 stops: never past the budget.
  w.nowMs = 0.0;
  w.ran.clear();
  EXPECT_EQ(schedule.run(shadows, 15.0, w.clock(), w.work()), 2);
  EXPECT_LE(w.nowMs, 15.0);
  // Light maps are measured apart: after the 6 ms shadow map, 4 ms light maps end at 10, 14 and
  // 18 ms; a fourth would end at 22 > 18.
  w.nowMs = 0.0;
  w.ran.clear();
  std::vector<MapJob> mixed{{1, 0, MapKind::Shadow}};
  for (int i = 1; i <= 5; ++i) mixed.push_back({2, i, MapKind::Light});
  schedule.run(mixed, 18.0, w.clock(), w.work());
  EXPECT_EQ(beams(w.ran), (std::vector<int>{0, 1, 2, 3}));
}

// Every frame progresses: the oldest job runs even when the budget is already spent.
TEST(MapSchedule, TheOldestAlwaysGoes) {
  MapSchedule schedule;
  FakeWork w;
  w.nowMs = 100.0;  // the frame has already used more than the budget
  std::vector<MapJob> jobs{{2, 4, MapKind::Shadow}, {1, 9, MapKind::Shadow}};
  EXPECT_EQ(schedule.run(jobs, 5.0, w.clock(), w.work()), 1);
  EXPECT_EQ(beams(w.ran), (std::vector<int>{9}));
}

// A job that has become unnecessary (its light map baked for another beam) costs nothing: it
// neither counts as the first nor replaces the last measured time.
TEST(MapSchedule, UnnecessaryJobsCostNothing) {
  MapSchedule schedule;
  double now = 0.0;
  std::vector<int> ran;
  const auto work = [&](const MapJob& j) {
    if (j.beam % 2 == 1) return false;
    now += 4.0;
    ran.push_back(j.beam);
    return true;
  };
  std::vector<MapJob> jobs;
  for (int i = 0; i < 6; ++i) jobs.push_back({1, i, MapKind::Light});
  EXPECT_EQ(schedule.run(jobs, 9.0, [&] { return now; }, work), 2);
  EXPECT_EQ(ran, (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(schedule.lastMs(MapKind::Light), 4.0);
}

TEST(MapSchedule, NoJobsNoWork) {
  MapSchedule schedule;
  FakeWork w;
  EXPECT_EQ(schedule.run({}, 10.0, w.clock(), w.work()), 0);
  EXPECT_TRUE(w.ran.empty());
}

}  // namespace
}  // namespace haze
