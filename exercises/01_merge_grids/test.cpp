#include <gtest/gtest.h>

#include "common/interface/merged_grid.hpp"
#include "exercise.hpp"

namespace {
void expect_same_as_library(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2) {
  const std::vector<double> mine = exercise::merge_breakpoints(t1.x, t2.x, 1e-12);
  const mortar::MergedGrid reference = mortar::merge_traces(t1, t2, 1e-12);
  ASSERT_EQ(mine.size(), reference.breakpoints.size());
  for (std::size_t i = 0; i < mine.size(); ++i) EXPECT_NEAR(mine[i], reference.breakpoints[i], 1e-13) << "breakpoint " << i;
}
}  // namespace

TEST(MergeGrids, union_of_two_nonmatching_grids) {
  expect_same_as_library(mortar::uniform_trace(1.0, 4), mortar::uniform_trace(1.0, 3));
  expect_same_as_library(mortar::uniform_trace(2.0, 7, 0.3, 1), mortar::uniform_trace(2.0, 11, 0.3, 2));
}

TEST(MergeGrids, nodes_1e14_apart_make_one_breakpoint) {
  // side 2 = side 1 moved by 1e-14, plus one node of its own at 0.55
  const mortar::InterfaceTrace t1 = mortar::uniform_trace(1.0, 10);
  std::vector<double> x2 = t1.x;
  for (int i = 1; i < 10; ++i) x2[i] += 1e-14;
  x2.insert(x2.begin() + 6, 0.55);
  const std::vector<double> merged = exercise::merge_breakpoints(t1.x, x2, 1e-12);
  EXPECT_EQ(merged.size(), 12u);
  for (std::size_t i = 1; i < merged.size(); ++i) EXPECT_GT(merged[i] - merged[i - 1], 0.04) << "sliver at " << merged[i];
}
