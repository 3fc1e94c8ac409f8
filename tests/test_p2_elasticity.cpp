// The six-node element: symmetric, exactly three rigid-body modes, its stated rule exact, and
// the energy of every quadratic field right.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "common/fem/mesh.hpp"
#include "common/fem/p2_elasticity.hpp"

using namespace mortar;

namespace {
const std::array<Eigen::Vector2d, 3> skewed = {Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(1.3, 0.1),
                                               Eigen::Vector2d(0.4, 0.9)};

// The six nodes: the vertices, then the midpoints of the edges 0-1, 1-2, 2-0.
std::array<Eigen::Vector2d, 6> nodes(const std::array<Eigen::Vector2d, 3>& x) {
  return {x[0], x[1], x[2], 0.5 * (x[0] + x[1]), 0.5 * (x[1] + x[2]), 0.5 * (x[2] + x[0])};
}

// Nodal values of a displacement field.
Eigen::Matrix<double, 12, 1> interpolate(const std::array<Eigen::Vector2d, 3>& x,
                                         const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& u) {
  Eigen::Matrix<double, 12, 1> v;
  const auto p = nodes(x);
  for (int a = 0; a < 6; ++a) v.segment<2>(2 * a) = u(p[a]);
  return v;
}
}  // namespace

TEST(P2Elasticity, element_matrix_is_symmetric) {
  const P2ElementMatrix K = p2_element_stiffness(skewed, Material(2.0, 0.3));
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-14 * K.cwiseAbs().maxCoeff());
}

TEST(P2Elasticity, has_exactly_three_rigid_body_modes) {
  const P2ElementMatrix K = p2_element_stiffness(skewed, Material(1.0, 0.25));
  const Eigen::SelfAdjointEigenSolver<P2ElementMatrix> eig(K);
  const auto& ev = eig.eigenvalues();
  const double largest = ev.maxCoeff();
  int zero = 0;
  for (int k = 0; k < 12; ++k) {
    EXPECT_GT(ev[k], -1e-12 * largest);
    if (std::fabs(ev[k]) < 1e-12 * largest) ++zero;
  }
  EXPECT_EQ(zero, 3);
  EXPECT_GT(ev[3], 1e-4 * largest);  // the fourth is well away from zero
  // the three are the translations and the rotation
  for (const auto& mode : {std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d&) { return Eigen::Vector2d(1, 0); }),
                           std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 1); }),
                           std::function<Eigen::Vector2d(const Eigen::Vector2d&)>(
                               [](const Eigen::Vector2d& p) { return Eigen::Vector2d(-p.y(), p.x()); })})
    EXPECT_LT((K * interpolate(skewed, mode)).norm(), 1e-13 * largest);
}

// B^T C B is a quadratic: the rule of degree 2 gives K to round-off, as one of degree 6 does;
// the one-point rule (degree 1 here: n = 1 gives degree 0) does not.
TEST(P2Elasticity, the_stated_rule_is_exact) {
  const Material m(3.0, 0.2);
  EXPECT_EQ(triangle_rule(p2_stiffness_degree).degree, 2);
  const P2ElementMatrix K2 = p2_element_stiffness(skewed, m), K6 = p2_element_stiffness(skewed, m, triangle_rule(6));
  EXPECT_LT((K2 - K6).cwiseAbs().maxCoeff(), 1e-13 * K6.cwiseAbs().maxCoeff());
  const P2ElementMatrix K0 = p2_element_stiffness(skewed, m, triangle_rule(0));
  EXPECT_GT((K0 - K6).cwiseAbs().maxCoeff(), 1e-2 * K6.cwiseAbs().maxCoeff());
}

// u^T K u = int_T eps(u) : C eps(u) for a quadratic u, the integral taken independently: the
// strain of u from its exact derivatives, by a rule of degree 6.
TEST(P2Elasticity, energy_of_a_quadratic_field_is_exact) {
  const Material m(1.5, 0.35);
  const auto u = [](const Eigen::Vector2d& p) {
    const double x = p.x(), y = p.y();
    return Eigen::Vector2d(0.3 * x * x - 0.7 * x * y + 0.2 * y + 1.1 * y * y, -0.4 * x * y + 0.9 * x * x + 0.5 * x - y);
  };
  const auto strain = [](const Eigen::Vector2d& p) {
    const double x = p.x(), y = p.y();
    const double ux_x = 0.6 * x - 0.7 * y, ux_y = -0.7 * x + 0.2 + 2.2 * y;
    const double uy_x = -0.4 * y + 1.8 * x + 0.5, uy_y = -0.4 * x - 1;
    return Eigen::Vector3d(ux_x, uy_y, ux_y + uy_x);
  };
  const TriangleRule rule = triangle_rule(6);
  const auto& x = skewed;
  const double area = 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  double energy = 0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const Eigen::Vector2d p = x[0] + rule.points[q].x() * (x[1] - x[0]) + rule.points[q].y() * (x[2] - x[0]);
    const Eigen::Vector3d e = strain(p);
    energy += area * rule.weights[q] * e.dot(m.voigt() * e);
  }
  const Eigen::Matrix<double, 12, 1> v = interpolate(x, u);
  EXPECT_NEAR(v.dot(p2_element_stiffness(x, m) * v), energy, 1e-13 * energy);
}

TEST(P2Elasticity, refuses_a_triangle_of_the_wrong_orientation) {
  const std::array<Eigen::Vector2d, 3> flipped = {skewed[0], skewed[2], skewed[1]};
  EXPECT_THROW(p2_element_stiffness(flipped, Material(1, 0.3)), std::invalid_argument);
}

TEST(P2Mesh, adds_one_midpoint_per_edge_and_keeps_the_sides_in_order) {
  RectangleSpec spec;
  spec.x1 = 2;
  spec.nx = 4;
  spec.ny = 3;
  const Mesh p1 = rectangle_mesh(spec);
  const Mesh m = p2_mesh(p1);
  const int edges = 4 * 4 + 3 * 5 + 4 * 3;  // horizontal, vertical, diagonal
  EXPECT_EQ(m.degree(), 2);
  EXPECT_EQ(p1.degree(), 1);
  EXPECT_EQ(m.num_nodes(), 20 + edges);
  EXPECT_EQ(m.triangles.size(), p1.triangles.size());
  const std::vector<int>& bottom = m.nodes_on(Side::bottom);
  ASSERT_EQ(bottom.size(), 9u);  // 2 n + 1 nodes on Gamma_c
  for (std::size_t k = 0; k < bottom.size(); ++k) {
    EXPECT_NEAR(m.nodes[bottom[k]].x(), 0.25 * k, 1e-14);
    EXPECT_NEAR(m.nodes[bottom[k]].y(), 0.0, 1e-14);
  }
  EXPECT_EQ(m.nodes_on(Side::left).size(), 7u);
  // every midpoint lies halfway along its edge
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((m.nodes[m.edge_nodes[t][k]] - 0.5 * (m.nodes[m.triangles[t][k]] + m.nodes[m.triangles[t][(k + 1) % 3]])).norm(), 1e-15);
  // the vertices keep their P1 numbers, the midpoints come after them
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) EXPECT_GE(m.edge_nodes[t][k], p1.num_nodes());
}

// a(u, v) = v^T K u for quadratic u and v over a jittered rectangle: the assembled matrix is
// exact on P2, the integral taken independently by a tensor Gauss rule on the rectangle.
TEST(P2Mesh, assembly_is_exact_for_quadratic_fields) {
  RectangleSpec spec;
  spec.x1 = 2;
  spec.nx = 5;
  spec.ny = 4;
  spec.jitter = 0.3;
  const Mesh m = p2_mesh(rectangle_mesh(spec));
  const Material material(1.7, 0.3);
  const SparseMatrix K = assemble_stiffness(m, material);
  struct Quadratic {
    Eigen::Matrix<double, 2, 6> c;  // u_i = c(i, .) . (1, x, y, x^2, xy, y^2)
    Eigen::Vector2d at(const Eigen::Vector2d& p) const {
      Eigen::Matrix<double, 6, 1> b;
      b << 1, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
      return c * b;
    }
    Eigen::Vector3d strain(const Eigen::Vector2d& p) const {
      Eigen::Matrix<double, 6, 1> dx, dy;
      dx << 0, 1, 0, 2 * p.x(), p.y(), 0;
      dy << 0, 0, 1, 0, p.x(), 2 * p.y();
      return {c.row(0).dot(dx), c.row(1).dot(dy), c.row(0).dot(dy) + c.row(1).dot(dx)};
    }
    Eigen::VectorXd nodal(const Mesh& mesh) const {
      Eigen::VectorXd v(mesh.num_dofs());
      for (int a = 0; a < mesh.num_nodes(); ++a) v.segment<2>(2 * a) = at(mesh.nodes[a]);
      return v;
    }
  };
  Quadratic u, v;
  u.c << 0.1, 0.3, -0.2, 0.5, -0.7, 0.2, -0.3, 0.4, 0.6, -0.1, 0.25, 0.8;
  v.c << 0.0, -0.5, 0.1, 0.3, 0.2, -0.6, 0.2, 0.1, -0.4, 0.7, -0.3, 0.1;
  const SegmentRule g = gauss_legendre(4);  // exact to degree 7 in each direction
  double exact = 0;
  for (std::size_t i = 0; i < g.points.size(); ++i)
    for (std::size_t j = 0; j < g.points.size(); ++j) {
      const Eigen::Vector2d p(2 * g.points[i], g.points[j]);
      exact += 2 * g.weights[i] * g.weights[j] * v.strain(p).dot(material.voigt() * u.strain(p));
    }
  const double computed = v.nodal(m).dot(K * u.nodal(m));
  EXPECT_NEAR(computed, exact, 1e-12 * std::fabs(exact));
  // and a P1 field is a P2 field: the rigid motions give K u = 0
  Quadratic rotation;
  rotation.c << 0.2, 0, -1, 0, 0, 0, -0.1, 1, 0, 0, 0, 0;
  EXPECT_LT((K * rotation.nodal(m)).norm(), 1e-12 * K.norm());
}
