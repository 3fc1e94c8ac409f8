#include <gtest/gtest.h>

#include "common/contact/two_bodies.hpp"

using namespace mortar;

TEST(TwoBodies, stack_on_gamma_c_with_block_diagonal_stiffness) {
  TwoBodyGeometry g;
  g.n1 = 4; g.m1 = 2; g.n2 = 6; g.m2 = 3; g.H1 = 0.4; g.H2 = 0.7;
  const TwoBodies b = make_two_bodies(g, Material(1, 0.3), Material(5, 0.2));
  EXPECT_EQ(b.num_dofs(), 2 * 5 * 3 + 2 * 7 * 4);
  EXPECT_EQ(b.offset(1), 30);
  for (int a : b.body(0).mesh.nodes_on(Side::bottom)) EXPECT_EQ(b.body(0).mesh.nodes[a].y(), 0.0);
  for (int a : b.body(1).mesh.nodes_on(Side::top)) EXPECT_EQ(b.body(1).mesh.nodes[a].y(), 0.0);
  EXPECT_DOUBLE_EQ(b.body(0).mesh.nodes[b.body(0).mesh.nodes_on(Side::top)[0]].y(), 0.4);
  EXPECT_DOUBLE_EQ(b.body(1).mesh.nodes[b.body(1).mesh.nodes_on(Side::bottom)[0]].y(), -0.7);
  const SparseMatrix K = b.stiffness();
  for (int k = 0; k < K.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(K, k); it; ++it)
      EXPECT_EQ(it.row() < 30, it.col() < 30) << "K couples the bodies at (" << it.row() << ", " << it.col() << ")";
  EXPECT_EQ(TwoBodies::normal_y(0), -1.0);
  EXPECT_EQ(TwoBodies::normal_y(1), 1.0);
}

TEST(TwoBodies, jitter_moves_the_two_traces_independently) {
  TwoBodyGeometry g;
  g.n1 = g.n2 = 8; g.m1 = g.m2 = 2; g.jitter = 0.3;
  const TwoBodies b = make_two_bodies(g, Material(1, 0.3), Material(1, 0.3));
  const auto& t1 = b.body(0).mesh.nodes_on(Side::bottom);
  const auto& t2 = b.body(1).mesh.nodes_on(Side::top);
  double differ = 0;
  for (std::size_t i = 0; i < t1.size(); ++i)
    differ = std::max(differ, std::fabs(b.body(0).mesh.nodes[t1[i]].x() - b.body(1).mesh.nodes[t2[i]].x()));
  EXPECT_GT(differ, 1e-3);
  EXPECT_EQ(b.body(0).mesh.nodes[t1.back()].x(), b.body(1).mesh.nodes[t2.back()].x());  // common end a2
}
