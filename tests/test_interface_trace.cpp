#include <gtest/gtest.h>

#include "common/interface_trace.hpp"

using namespace mortar;

TEST(InterfaceTrace, trace_of_a_jittered_mesh_is_sorted_and_spans_gamma_c) {
  RectangleSpec s;
  s.x1 = 2; s.nx = 13; s.ny = 4; s.jitter = 0.4;
  const Mesh mesh = rectangle_mesh(s);
  const InterfaceTrace t = trace_on_side(mesh, Side::bottom);
  ASSERT_EQ(t.num_nodes(), 14);
  EXPECT_EQ(t.x.front(), 0.0);
  EXPECT_EQ(t.x.back(), 2.0);
  for (int i = 0; i < t.num_nodes(); ++i) EXPECT_EQ(mesh.nodes[t.nodes[i]].x(), t.x[i]);
}

TEST(InterfaceTrace, locates_points_and_evaluates_p1_functions) {
  const InterfaceTrace t = uniform_trace(1.0, 4);
  EXPECT_EQ(t.element_containing(0.0), 0);
  EXPECT_EQ(t.element_containing(0.3), 1);
  EXPECT_EQ(t.element_containing(1.0), 3);
  const std::vector<double> w = {0, 1, 0, 2, 2};
  EXPECT_DOUBLE_EQ(t.evaluate(w, 0.125), 0.5);
  EXPECT_DOUBLE_EQ(t.evaluate(w, 0.625), 1.0);
  EXPECT_DOUBLE_EQ(t.evaluate(w, 1.0), 2.0);
}

TEST(InterfaceTrace, rejects_bad_grids) {
  EXPECT_THROW(uniform_trace(1.0, 0), std::invalid_argument);
  EXPECT_THROW(uniform_trace(-1.0, 3), std::invalid_argument);
  EXPECT_THROW(uniform_trace(1.0, 3, 0.9), std::invalid_argument);
}
