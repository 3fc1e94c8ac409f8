#include <gtest/gtest.h>

#include "common/mesh.hpp"

using namespace mortar;

TEST(Mesh, rectangle_has_expected_counts_and_area) {
  RectangleSpec s;
  s.x0 = -1; s.x1 = 2; s.y0 = 0; s.y1 = 0.5; s.nx = 6; s.ny = 3;
  const Mesh m = rectangle_mesh(s);
  EXPECT_EQ(m.num_nodes(), 7 * 4);
  EXPECT_EQ(m.triangles.size(), 2u * 6 * 3);
  double area = 0;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    EXPECT_GT(m.area(t), 0) << "triangle " << t << " is not counter-clockwise";
    area += m.area(t);
  }
  EXPECT_NEAR(area, 1.5, 1e-13);
  EXPECT_EQ(m.nodes_on(Side::bottom).size(), 7u);
  EXPECT_EQ(m.nodes_on(Side::left).size(), 4u);
  for (int a : m.nodes_on(Side::top)) EXPECT_DOUBLE_EQ(m.nodes[a].y(), 0.5);
  for (int a : m.nodes_on(Side::right)) EXPECT_DOUBLE_EQ(m.nodes[a].x(), 2.0);
}

TEST(Mesh, jitter_keeps_triangles_valid_and_sides_straight) {
  RectangleSpec s;
  s.nx = 20; s.ny = 20; s.jitter = 0.4; s.seed = 7;
  const Mesh m = rectangle_mesh(s);
  double area = 0;
  // each triangle keeps at least (1 - 2 jitter) = 20% of its nominal area 1/800
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    EXPECT_GT(m.area(t), 0.2 / 800) << "triangle " << t;
    area += m.area(t);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  const auto& bottom = m.nodes_on(Side::bottom);
  bool moved = false;
  for (size_t i = 0; i < bottom.size(); ++i) {
    EXPECT_EQ(m.nodes[bottom[i]].y(), 0.0);  // nodes slide along their side only
    if (i > 0) {
      EXPECT_GT(m.nodes[bottom[i]].x(), m.nodes[bottom[i - 1]].x());
    }
    moved = moved || std::fabs(m.nodes[bottom[i]].x() - 0.05 * i) > 1e-6;
  }
  EXPECT_TRUE(moved) << "jitter should move the nodes of Gamma_c along it";
  EXPECT_EQ(m.nodes[bottom.front()].x(), 0.0);
  EXPECT_EQ(m.nodes[bottom.back()].x(), 1.0);
}

TEST(Mesh, grading_clusters_rows_towards_the_chosen_side) {
  RectangleSpec s;
  s.nx = 2; s.ny = 10; s.grading = 2;
  s.grade_towards = Side::top;
  const Mesh m = rectangle_mesh(s);
  const auto& left = m.nodes_on(Side::left);
  const double first = m.nodes[left[1]].y() - m.nodes[left[0]].y();
  const double last = m.nodes[left[10]].y() - m.nodes[left[9]].y();
  EXPECT_LT(last, first / 5);
  EXPECT_DOUBLE_EQ(m.nodes[left.back()].y(), 1.0);
}

TEST(Mesh, rejects_bad_specs) {
  RectangleSpec s;
  s.nx = 0;
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
  s.nx = 2; s.jitter = 0.45;
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
  s.jitter = 0; s.x1 = s.x0;
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
}
