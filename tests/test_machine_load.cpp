// The machine's load during a timed run: other processes' CPU time is the machine's busy time
// less the program's own, shared over the wall time and the cores.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <unistd.h>

#include "common/timing/machine_load.hpp"

namespace {
int cores() { return static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN))); }
}  // namespace

TEST(MachineLoad, other_work_is_the_busy_time_the_program_did_not_spend) {
  // 10 s of wall time; the machine was busy 6 s, the program's ranks used 4 s of it
  const mortar::CpuClock start{100.0, 1.0}, end{106.0, 3.0};
  const mortar::MachineLoad load = mortar::machine_load(start, end, 4.0, 10.0);
  EXPECT_EQ(load.cores, cores());
  EXPECT_NEAR(load.other_work_share, 2.0 / (10.0 * cores()), 1e-12);
}

TEST(MachineLoad, a_quiet_machine_gives_meaningful_timings_and_a_busy_one_does_not) {
  // the program alone: all busy time its own
  const mortar::MachineLoad quiet = mortar::machine_load({50.0, 0.0}, {52.0, 2.0}, 2.0, 1.0);
  EXPECT_DOUBLE_EQ(quiet.other_work_share, 0.0);
  EXPECT_TRUE(quiet.meaningful());
  EXPECT_NE(quiet.describe().find("timings meaningful"), std::string::npos) << quiet.describe();
  // others took as much CPU as every core for the whole run
  const double wall = 2.0;
  const mortar::MachineLoad busy = mortar::machine_load({0.0, 0.0}, {wall * cores() + 1.0, 1.0}, 1.0, wall);
  EXPECT_DOUBLE_EQ(busy.other_work_share, 1.0);
  EXPECT_FALSE(busy.meaningful());
  EXPECT_NE(busy.describe().find("NOT meaningful"), std::string::npos) << busy.describe();
}

TEST(MachineLoad, the_clock_reads_this_machine) {
  const mortar::CpuClock a = mortar::CpuClock::now();
  volatile double x = 0;
  for (int i = 0; i < 20000000; ++i) x = x + 1e-9 * i;
  const mortar::CpuClock b = mortar::CpuClock::now();
  EXPECT_GT(a.machine_busy_s, 0.0) << "/proc/stat unreadable";
  EXPECT_GE(b.machine_busy_s, a.machine_busy_s);
  EXPECT_GT(b.own_s, a.own_s) << "the loop took no CPU time";
}
