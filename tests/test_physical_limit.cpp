// Timing a level against its physical limit: how often each runs, that the fastest run is
// kept with its spread, and that the level's own phases reach its profile column.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "common/fem/dirichlet.hpp"
#include "common/linalg/physical_limit.hpp"
#include "common/timing/stopwatch.hpp"

using namespace mortar;

namespace {
// A small clamped block: the limit's K, cheap to assemble and factorize.
SparseMatrix small_K() {
  RectangleSpec s;
  s.nx = 6; s.ny = 6;
  const Mesh mesh = rectangle_mesh(s);
  DirichletData data;
  prescribe_on_sides(data, mesh, {Side::bottom}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 0); });
  return eliminate_dirichlet(assemble_stiffness(mesh, Material(1, 0.3)), Eigen::VectorXd::Zero(mesh.num_dofs()), data).K;
}

double seconds_of(const ProfileColumn& c, const std::string& phase) {
  for (const auto& [name, s] : c.phases)
    if (name == phase) return s;
  return -1;  // not there
}
}  // namespace

// Repetitions{min, max, budget}: with no budget the level and its limit run exactly `min`
// times each; with a budget far beyond the runs, `max` caps them.
TEST(PhysicalLimit, repetitions_run_the_level_and_the_limit_min_or_max_times) {
  struct Case {
    Repetitions r;
    int runs;
  };
  for (const Case c : {Case{{2, 5, 0.0}, 2}, Case{{3, 3, 10.0}, 3}}) {
    int levels = 0, limits = 0;
    const TimedLevel t = time_against_limit([&] { ++levels; },
                                            [&] {
                                              ++limits;
                                              return small_K();
                                            },
                                            c.r);
    EXPECT_EQ(levels, c.runs) << "Repetitions{" << c.r.min << ", " << c.r.max << ", " << c.r.budget_s << "}";
    EXPECT_EQ(limits, c.runs);
    EXPECT_EQ(t.repeats, c.runs);
  }
}

// MORTAR_TIME_ONCE=1 (set for the runs under the sanitizers): one run of each, whatever the
// repetitions ask; any other value leaves them as they are.
TEST(PhysicalLimit, time_once_runs_each_once) {
  for (const char* value : {"1", "0"}) {
    ASSERT_EQ(setenv("MORTAR_TIME_ONCE", value, 1), 0);
    int levels = 0, limits = 0;
    const TimedLevel t = time_against_limit([&] { ++levels; },
                                            [&] {
                                              ++limits;
                                              return small_K();
                                            },
                                            {3, 3, 10.0});
    unsetenv("MORTAR_TIME_ONCE");
    const int expected = std::string(value) == "1" ? 1 : 3;
    EXPECT_EQ(levels, expected) << "MORTAR_TIME_ONCE=" << value;
    EXPECT_EQ(limits, expected);
    EXPECT_EQ(t.repeats, expected);
  }
}

// The minimum is kept: one run of the level sleeps 150 ms and one 10 ms, so the kept time is
// the short one (the mean would be over 75 ms), the spread is large, and the profile column
// is that of the fastest run, with the phase the level opened and the limit's assembly.
TEST(PhysicalLimit, the_fastest_run_is_kept_with_its_spread_and_phases) {
  std::vector<double> level_seconds;
  int call = 0;
  const TimedLevel t = time_against_limit(
      [&] {
        const Stopwatch clock;
        const ProfilePhase phase("coupling");
        std::this_thread::sleep_for(std::chrono::milliseconds(call++ == 0 ? 150 : 10));
        level_seconds.push_back(clock.seconds());
      },
      small_K, Repetitions{2, 5, 0.0});
  ASSERT_EQ(level_seconds.size(), 2u);
  EXPECT_EQ(t.repeats, 2);
  EXPECT_GE(t.time_s, 0.010);
  EXPECT_LT(t.time_s, 0.075) << "not the fastest run";
  EXPECT_LE(t.time_s, *std::max_element(level_seconds.begin(), level_seconds.end()));
  EXPECT_GT(t.limit_s, 0.0);
  EXPECT_GT(t.time_spread, 0.5);
  EXPECT_GE(t.limit_spread, 0.0);
  EXPECT_EQ(t.profile.title, "level");
  EXPECT_EQ(t.profile.total, t.time_s);
  EXPECT_GE(seconds_of(t.profile, "coupling"), 0.010) << "the level's phase is missing";
  EXPECT_LE(seconds_of(t.profile, "coupling"), t.time_s);
  EXPECT_EQ(t.limit_profile.title, "limit");
  EXPECT_GE(seconds_of(t.limit_profile, "assembly"), 0.0) << "the limit's assembly phase is missing";
  EXPECT_LT(seconds_of(t.profile, "assembly"), 0.0) << "the limit's phases leaked into the level's";
}
