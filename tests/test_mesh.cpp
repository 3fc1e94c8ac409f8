#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "common/fem/mesh.hpp"

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

TEST(Mesh, graded_nodes_follow_the_target_cell_size) {
  // a constant size that divides the interval gives exactly its uniform cells
  const std::vector<double> uniform = graded_nodes(0, 1, [](double) { return 0.125; });
  ASSERT_EQ(uniform.size(), 9u);
  for (std::size_t k = 0; k < uniform.size(); ++k) EXPECT_NEAR(uniform[k], 0.125 * k, 1e-12);
  // size 0.001 + 0.1 |x - 0.3|: cells of about 0.001 at x = 0.3, growing by about 10% a cell
  const auto size = [](double x) { return 0.001 + 0.1 * std::fabs(x - 0.3); };
  const std::vector<double> t = graded_nodes(0, 1, size);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 1.0);
  double smallest = 1;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double cell = t[k] - t[k - 1];
    ASSERT_GT(cell, 0) << "cell " << k;
    smallest = std::min(smallest, cell);
    // never longer than the target anywhere in the cell (rounding up N only shortens cells)
    EXPECT_LE(cell, 1.001 * std::max(size(t[k - 1]), size(t[k]))) << "cell " << k << " at " << t[k - 1];
    EXPECT_GE(cell, 0.85 * std::min(size(t[k - 1]), size(t[k]))) << "cell " << k << " at " << t[k - 1];
  }
  EXPECT_NEAR(smallest, 0.001, 2e-4);
  EXPECT_LT(t.size(), 120u);  // (ln(1 + 0.1 * 0.3 / 0.001) + ln(1 + 0.1 * 0.7 / 0.001)) / 0.1 + 1 = 78
}

TEST(Mesh, explicit_nodes_give_a_tensor_product_grid) {
  RectangleSpec s;
  s.x0 = 0; s.x1 = 2; s.y0 = -1; s.y1 = 0;
  s.x_nodes = {0, 0.1, 0.5, 2};
  s.y_nodes = {-1, -0.2, -0.05, 0};
  const Mesh m = rectangle_mesh(s);
  EXPECT_EQ(m.num_nodes(), 16);
  EXPECT_EQ(m.triangles.size(), 18u);
  double area = 0;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    EXPECT_GT(m.area(t), 0) << "triangle " << t;
    area += m.area(t);
  }
  EXPECT_NEAR(area, 2.0, 1e-13);
  const auto& top = m.nodes_on(Side::top);
  ASSERT_EQ(top.size(), 4u);
  for (std::size_t i = 0; i < top.size(); ++i) {
    EXPECT_EQ(m.nodes[top[i]].x(), s.x_nodes[i]);
    EXPECT_EQ(m.nodes[top[i]].y(), 0.0);
  }
  const auto& left = m.nodes_on(Side::left);
  for (std::size_t j = 0; j < left.size(); ++j) EXPECT_EQ(m.nodes[left[j]].y(), s.y_nodes[j]);
}

TEST(Mesh, jittered_graded_nodes_stay_ordered) {
  RectangleSpec s;
  s.x_nodes = graded_nodes(0, 1, [](double x) { return 0.002 + 0.2 * std::fabs(x - 0.5); });
  s.ny = 4;
  s.jitter = 0.4;
  const Mesh m = rectangle_mesh(s);
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) EXPECT_GT(m.area(t), 0) << "triangle " << t;
}

TEST(Mesh, rejects_explicit_nodes_that_do_not_span_the_rectangle_or_go_back) {
  RectangleSpec s;
  s.x_nodes = {0, 0.5, 0.9};  // stops short of x1 = 1
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
  s.x_nodes = {0, 0.6, 0.4, 1};
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
  s.x_nodes = {0, 1};
  s.y_nodes = {0};
  EXPECT_THROW(rectangle_mesh(s), std::invalid_argument);
  EXPECT_THROW(graded_nodes(0, 1, [](double) { return 0.0; }), std::invalid_argument);
  EXPECT_THROW(graded_nodes(1, 1, [](double) { return 0.1; }), std::invalid_argument);
}

// Bands of a jittered, graded mesh, laid side by side, are the whole mesh: the same
// coordinates (bit for bit), the same triangles shifted by the band's first node, and the
// rectangle's sides only where a band reaches them.
TEST(Mesh, bands_rebuild_the_whole_mesh_with_its_jitter) {
  RectangleSpec s;
  s.nx = 7; s.ny = 9; s.jitter = 0.3; s.grading = 2; s.seed = 5;
  const Mesh whole = rectangle_mesh(s);
  std::size_t triangles = 0;
  for (const auto& [row0, row1] : std::vector<std::pair<int, int>>{{0, 2}, {2, 3}, {3, 9}}) {
    const Mesh band = rectangle_band(s, row0, row1);
    const int shift = row0 * (s.nx + 1);
    ASSERT_EQ(band.num_nodes(), (row1 - row0 + 1) * (s.nx + 1));
    for (int k = 0; k < band.num_nodes(); ++k) EXPECT_EQ(band.nodes[k], whole.nodes[k + shift]) << "node " << k;
    for (std::size_t t = 0; t < band.triangles.size(); ++t)
      for (int a = 0; a < 3; ++a) EXPECT_EQ(band.triangles[t][a] + shift, whole.triangles[triangles + t][a]);
    triangles += band.triangles.size();
    EXPECT_EQ(band.nodes_on(Side::bottom).size(), row0 == 0 ? 8u : 0u);
    EXPECT_EQ(band.nodes_on(Side::top).size(), row1 == 9 ? 8u : 0u);
    ASSERT_EQ(band.nodes_on(Side::left).size(), static_cast<std::size_t>(row1 - row0 + 1));
    EXPECT_EQ(band.nodes_on(Side::left).front() + shift, whole.nodes_on(Side::left)[row0]);
  }
  EXPECT_EQ(triangles, whole.triangles.size());
  EXPECT_EQ(rectangle_band(s, 4, 4).num_nodes(), 0);
  EXPECT_THROW(rectangle_band(s, 3, 10), std::invalid_argument);
  EXPECT_THROW(rectangle_band(s, 5, 4), std::invalid_argument);
}
