// The memory estimate: what a run needs, what the machine has, and the refusal between them.
#include "common/linalg/memory_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

TEST(MemoryEstimate, reads_mem_available_in_kilobytes) {
  const std::string meminfo = "MemTotal:       24683656 kB\nMemFree:         1000000 kB\n"
                              "MemAvailable:   23869088 kB\nBuffers:          1234 kB\n";
  EXPECT_DOUBLE_EQ(mortar::mem_available_bytes(meminfo), 23869088.0 * 1024);
  EXPECT_TRUE(std::isinf(mortar::mem_available_bytes("MemTotal: 1 kB\n")));
}

TEST(MemoryEstimate, grows_with_the_dofs) {
  const double small = mortar::run_bytes(1e5, mortar::bytes_per_dof_single_solve);
  const double large = mortar::run_bytes(1e6, mortar::bytes_per_dof_single_solve);
  EXPECT_NEAR(large - small, 9e5 * mortar::bytes_per_dof_single_solve, 1.0);
  // the measured peak of ch02_p1_triangles at 2,101,250 dofs was 5.69 GB: never below it
  EXPECT_GT(mortar::run_bytes(2101250, mortar::bytes_per_dof_single_solve), 5.69e9);
}

TEST(MemoryEstimate, refuses_what_the_machine_cannot_hold_and_says_how_much) {
  const mortar::MachineMemory machine{8e9, std::numeric_limits<double>::infinity()};
  EXPECT_EQ(mortar::memory_shortfall(1e5, 3000, machine), "");
  const std::string message = mortar::memory_shortfall(1e7, 3000, machine);
  EXPECT_NE(message.find("1e+07 dofs"), std::string::npos) << message;
  EXPECT_NE(message.find("GB of memory"), std::string::npos) << message;
  EXPECT_NE(message.find("8 GB available"), std::string::npos) << message;
}

TEST(MemoryEstimate, an_address_space_limit_counts_like_missing_memory) {
  const mortar::MachineMemory machine{8e9, 0.5e9};
  EXPECT_DOUBLE_EQ(machine.usable(), 0.5e9);
  const std::string message = mortar::memory_shortfall(2e5, 3000, machine);
  EXPECT_NE(message.find("ulimit -v"), std::string::npos) << message;
}

TEST(MemoryEstimate, the_machine_reports_some_memory) {
  const mortar::MachineMemory m = mortar::machine_memory();
  EXPECT_GT(m.usable(), 0);
}

}  // namespace
