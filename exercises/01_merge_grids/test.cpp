#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include "common/interface/merged_grid.hpp"
#include "exercise.hpp"

namespace {
void expect_same_as_library(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2) {
  const std::vector<double> mine = exercise::merge_breakpoints(t1.x, t2.x, 1e-12);
  const mortar::MergedGrid reference = mortar::merge_traces(t1, t2, 1e-12);
  ASSERT_EQ(mine.size(), reference.breakpoints.size());
  for (std::size_t i = 0; i < mine.size(); ++i) EXPECT_NEAR(mine[i], reference.breakpoints[i], 1e-13) << "breakpoint " << i;
}

// The three conditions of the README, checked on y for the points of x1 and x2 together.
void expect_the_three_conditions(const std::vector<double>& x1, const std::vector<double>& x2, double rel_tol,
                                 const std::vector<double>& y) {
  std::vector<double> all(x1);
  all.insert(all.end(), x2.begin(), x2.end());
  std::sort(all.begin(), all.end());
  const double tol = rel_tol * (x1.back() - x1.front());
  ASSERT_FALSE(y.empty());
  for (double q : y) EXPECT_TRUE(std::find(all.begin(), all.end(), q) != all.end()) << q << " is no node of either trace";
  EXPECT_EQ(y.front(), all.front()) << "the first breakpoint is the smallest node";
  EXPECT_EQ(y.back(), all.back()) << "the last breakpoint is the largest node";
  for (std::size_t j = 1; j < y.size(); ++j) EXPECT_GT(y[j] - y[j - 1], tol) << "sliver [" << y[j - 1] << ", " << y[j] << "]";
  for (double p : all) {
    bool covered = all.back() - p <= tol;
    for (double q : y) covered = covered || (q <= p && p - q <= tol);
    EXPECT_TRUE(covered) << "node " << p << " is dropped, yet no kept point lies at most tol before it";
  }
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

// Worked by hand from the three conditions, with tau = 1e-3 and L = 1, so tau L = 1e-3.
TEST(MergeGrids, cases_worked_by_hand) {
  using V = std::vector<double>;
  // 0.5, 0.5006, 0.5012: 0.5 is the first node more than 1e-3 after the kept 0, so it is kept;
  // 0.5006 lies 0.6e-3 after it and goes, 0.5012 lies 1.2e-3 after it and stays. Comparing each
  // node with its neighbour would drop both, and leave 0.5012 1.2e-3 from every breakpoint.
  EXPECT_EQ(exercise::merge_breakpoints(V{0, 1}, V{0, 0.5, 0.5006, 0.5012, 1}, 1e-3), (V{0, 0.5, 0.5012, 1}));
  // side 2 has a node 0.4e-3 before the shared end: a scan from the left keeps 0.9996 and drops
  // 1; condition 1 wants 1, and condition 2 then forbids 0.9996 (the library keeps 1 as well).
  EXPECT_EQ(exercise::merge_breakpoints(V{0, 0.5, 1}, V{0, 0.9996, 1}, 1e-3), (V{0, 0.5, 1}));
  // side 2 covers the middle of side 1 only (the library refuses traces that do not share ends)
  EXPECT_EQ(exercise::merge_breakpoints(V{0, 1}, V{0.25, 0.75}, 1e-3), (V{0, 0.25, 0.75, 1}));
  // side 2 sticks out of both ends by 0.4e-3: its ends are the extremes, side 1's are dropped
  EXPECT_EQ(exercise::merge_breakpoints(V{0, 0.5, 1}, V{-0.0004, 0.3, 1.0004}, 1e-3), (V{-0.0004, 0.3, 0.5, 1.0004}));
}

TEST(MergeGrids, random_traces_with_clusters_meet_the_three_conditions) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-2.0, 2.0);
  std::uniform_int_distribution<int> count(1, 10);
  const double tau = 1e-2;  // L = 1
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> x1{0.0, 1.0}, x2;
    for (int k = count(rng); k > 0; --k) x1.push_back(unit(rng));
    std::sort(x1.begin(), x1.end());
    for (double p : x1) {  // nodes of side 2 near those of side 1, some in chains 0.6 tau apart
      x2.push_back(p + offset(rng) * tau);
      if (unit(rng) < 0.3)
        for (int k = 1; k <= 3; ++k) x2.push_back(p + 0.6 * k * tau);
    }
    for (int k = count(rng); k > 0; --k) x2.push_back(unit(rng));
    std::sort(x2.begin(), x2.end());
    const std::vector<double> y = exercise::merge_breakpoints(x1, x2, tau);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_the_three_conditions(x1, x2, tau, y);
  }
}

TEST(MergeGrids, refuses_an_empty_side_1_or_a_tolerance_out_of_range) {
  using V = std::vector<double>;
  EXPECT_THROW(exercise::merge_breakpoints(V{0.0}, V{0, 1}, 1e-3), std::invalid_argument);
  EXPECT_THROW(exercise::merge_breakpoints(V{1, 1}, V{0, 1}, 1e-3), std::invalid_argument);
  EXPECT_THROW(exercise::merge_breakpoints(V{0, 1}, V{0, 1}, -1e-3), std::invalid_argument);
  EXPECT_THROW(exercise::merge_breakpoints(V{0, 1}, V{0, 1}, 1.0), std::invalid_argument);
}
