#include <gtest/gtest.h>

#include "common/interface/merged_grid.hpp"

using namespace mortar;

TEST(MergedGrid, holds_the_union_of_both_traces) {
  const InterfaceTrace t1 = uniform_trace(1.0, 4), t2 = uniform_trace(1.0, 3);
  const MergedGrid g = merge_traces(t1, t2);
  // 0, 1/4, 1/3, 1/2, 2/3, 3/4, 1
  ASSERT_EQ(g.breakpoints.size(), 7u);
  ASSERT_EQ(g.segments.size(), 6u);
  for (const auto& s : g.segments) {
    EXPECT_GE(s.a, t1.x[s.element1]);
    EXPECT_LE(s.b, t1.x[s.element1 + 1]);
    EXPECT_GE(s.a, t2.x[s.element2]);
    EXPECT_LE(s.b, t2.x[s.element2 + 1]);
  }
}

TEST(MergedGrid, traces_1e14_apart_give_no_sliver_segment) {
  InterfaceTrace t1 = uniform_trace(1.0, 10), t2 = uniform_trace(1.0, 10);
  for (int i = 1; i < 10; ++i) t2.x[i] += (i % 2 ? 1e-14 : -1e-14);
  const MergedGrid g = merge_traces(t1, t2);
  ASSERT_EQ(g.segments.size(), 10u);
  for (std::size_t s = 0; s < g.segments.size(); ++s) {
    EXPECT_EQ(g.breakpoints[s], t1.x[s]) << "side 1's node represents the merged pair";
    EXPECT_EQ(g.segments[s].element1, static_cast<int>(s));
    EXPECT_EQ(g.segments[s].element2, static_cast<int>(s));
  }
}

TEST(MergedGrid, traces_must_share_their_end_points) {
  const InterfaceTrace t1 = uniform_trace(1.0, 4), t2 = uniform_trace(1.1, 4);
  EXPECT_THROW(merge_traces(t1, t2), std::invalid_argument);
}

// The merging tolerance is relative to the length of Gamma_c: the same traces in any unit give
// the same grid. An absolute 1e-12 would leave nodes 1e-10 apart on L = 1e4 as slivers (19
// segments), and merge distinct nodes 5e-13 apart on L = 1e-4.
TEST(MergedGrid, tolerance_is_relative_to_the_length_of_gamma_c) {
  for (double L : {1e-4, 1.0, 1e4}) {
    InterfaceTrace t1 = uniform_trace(L, 10), t2 = uniform_trace(L, 10);
    for (int i = 1; i < 10; ++i) t2.x[i] += 1e-14 * L;  // the same nodes, up to round-off
    EXPECT_EQ(merge_traces(t1, t2).segments.size(), 10u) << "L = " << L;
    InterfaceTrace t3 = uniform_trace(L, 10);
    for (int i = 1; i < 10; ++i) t3.x[i] += 5e-9 * L;  // distinct nodes, 5e-9 L apart
    EXPECT_EQ(merge_traces(t1, t3).segments.size(), 19u) << "L = " << L;
  }
}
