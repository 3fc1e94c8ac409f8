// The six-node element: symmetric, exactly three rigid-body modes, its stated rule exact, and
// the energy of every quadratic field right.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "common/fem/errors.hpp"
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

// A quadratic displacement field, u_i = c(i, .) . (1, x, y, x^2, xy, y^2), its derivatives and
// its nodal values (on a P2 mesh, its interpolant is itself).
struct Quadratic {
  Eigen::Matrix<double, 2, 6> c;
  Eigen::Vector2d at(const Eigen::Vector2d& p) const {
    Eigen::Matrix<double, 6, 1> b;
    b << 1, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
    return c * b;
  }
  Eigen::Matrix2d grad(const Eigen::Vector2d& p) const {  // (grad u)_{ij} = d u_i / d x_j
    Eigen::Matrix<double, 6, 1> dx, dy;
    dx << 0, 1, 0, 2 * p.x(), p.y(), 0;
    dy << 0, 0, 1, 0, p.x(), 2 * p.y();
    Eigen::Matrix2d G;
    G << c.row(0).dot(dx), c.row(0).dot(dy), c.row(1).dot(dx), c.row(1).dot(dy);
    return G;
  }
  Eigen::Vector3d strain(const Eigen::Vector2d& p) const {
    const Eigen::Matrix2d G = grad(p);
    return {G(0, 0), G(1, 1), G(0, 1) + G(1, 0)};
  }
  Eigen::VectorXd nodal(const Mesh& mesh) const {
    Eigen::VectorXd v(mesh.num_dofs());
    for (int a = 0; a < mesh.num_nodes(); ++a) v.segment<2>(2 * a) = at(mesh.nodes[a]);
    return v;
  }
};

// The jittered rectangle [0, 2] x [0, 1] of the P2 mesh tests (its sides stay straight).
Mesh jittered_p2_rectangle() {
  RectangleSpec spec;
  spec.x1 = 2;
  spec.nx = 5;
  spec.ny = 4;
  spec.jitter = 0.3;
  return p2_mesh(rectangle_mesh(spec));
}

// int over [0, 2] x [0, 1] of a polynomial of degree <= 7 in each variable, by a tensor Gauss rule.
double integral_over_rectangle(const std::function<double(const Eigen::Vector2d&)>& h) {
  const SegmentRule g = gauss_legendre(4);
  double sum = 0;
  for (std::size_t i = 0; i < g.points.size(); ++i)
    for (std::size_t j = 0; j < g.points.size(); ++j)
      sum += 2 * g.weights[i] * g.weights[j] * h(Eigen::Vector2d(2 * g.points[i], g.points[j]));
  return sum;
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
  const Mesh m = jittered_p2_rectangle();
  const Material material(1.7, 0.3);
  const SparseMatrix K = assemble_stiffness(m, material);
  Quadratic u, v;
  u.c << 0.1, 0.3, -0.2, 0.5, -0.7, 0.2, -0.3, 0.4, 0.6, -0.1, 0.25, 0.8;
  v.c << 0.0, -0.5, 0.1, 0.3, 0.2, -0.6, 0.2, 0.1, -0.4, 0.7, -0.3, 0.1;
  const double exact = integral_over_rectangle(
      [&](const Eigen::Vector2d& p) { return v.strain(p).dot(material.voigt() * u.strain(p)); });
  const double computed = v.nodal(m).dot(K * u.nodal(m));
  EXPECT_NEAR(computed, exact, 1e-12 * std::fabs(exact));
  // and a P1 field is a P2 field: the rigid motions give K u = 0
  Quadratic rotation;
  rotation.c << 0.2, 0, -1, 0, 0, 0, -0.1, 1, 0, 0, 0, 0;
  EXPECT_LT((K * rotation.nodal(m)).norm(), 1e-12 * K.norm());
}

// The P2 shape functions sum to one, so the x-loads of a constant f add up to f_x * area; for
// a linear f, v^T F = int f . v for a quadratic v (f . v is cubic: the rule of degree 1 + 2 is
// exact, the one of degree 1 alone would not be).
TEST(P2Loads, body_force_is_exact_for_quadratic_fields) {
  const Mesh m = jittered_p2_rectangle();
  const Eigen::VectorXd F0 = body_force_vector(m, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0.7, -0.4); }, 0);
  double fx = 0, fy = 0;
  for (int a = 0; a < m.num_nodes(); ++a) fx += F0[2 * a], fy += F0[2 * a + 1];
  EXPECT_NEAR(fx, 0.7 * 2, 1e-14);
  EXPECT_NEAR(fy, -0.4 * 2, 1e-14);

  const VectorField f = [](const Eigen::Vector2d& p) { return p; };
  Quadratic v;
  v.c << 0.0, -0.5, 0.1, 0.3, 0.2, -0.6, 0.2, 0.1, -0.4, 0.7, -0.3, 0.1;
  const double exact = integral_over_rectangle([&](const Eigen::Vector2d& p) { return f(p).dot(v.at(p)); });
  EXPECT_NEAR(v.nodal(m).dot(body_force_vector(m, f, 1)), exact, 1e-13 * std::fabs(exact));
}

// A traction g = (x^2, 1) on the bottom (y = 0, its nodes jittered along it): v^T F = int g . v
// for a quadratic v, a quartic that two points (n_gauss) would miss and three integrate exactly.
TEST(P2Loads, traction_is_exact_for_quadratic_fields) {
  const Mesh m = jittered_p2_rectangle();
  const VectorField g = [](const Eigen::Vector2d& p) { return Eigen::Vector2d(p.x() * p.x(), 1); };
  Quadratic v;
  v.c << 0.4, -0.5, 0.1, 0.3, 0.2, -0.6, 0.2, 0.1, -0.4, -0.7, -0.3, 0.1;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(m.num_dofs());
  add_traction(F, m, Side::bottom, g, 2);
  const SegmentRule rule = gauss_legendre(4);
  double exact = 0;
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const Eigen::Vector2d p(2 * rule.points[q], 0);
    exact += 2 * rule.weights[q] * g(p).dot(v.at(p));
  }
  EXPECT_NEAR(v.nodal(m).dot(F), exact, 1e-13 * std::fabs(exact));
}

namespace {
ExactSolution exact_solution(const Quadratic& u) {
  return {[u](const Eigen::Vector2d& p) { return u.at(p); }, [u](const Eigen::Vector2d& p) { return u.grad(p); }};
}

// A cubic field on the unit square and its P2 interpolant on an n x n mesh.
ErrorNorms cubic_interpolation_error(int n) {
  RectangleSpec spec;
  spec.nx = spec.ny = n;
  const Mesh m = p2_mesh(rectangle_mesh(spec));
  const ExactSolution cubic{
      [](const Eigen::Vector2d& p) {
        const double x = p.x(), y = p.y();
        return Eigen::Vector2d(x * x * x - 2 * x * y * y + 0.5 * y, y * y * y + 3 * x * x * y - x);
      },
      [](const Eigen::Vector2d& p) {
        const double x = p.x(), y = p.y();
        Eigen::Matrix2d G;
        G << 3 * x * x - 2 * y * y, -4 * x * y + 0.5, 6 * x * y - 1, 3 * y * y + 3 * x * x;
        return G;
      }};
  Eigen::VectorXd u(m.num_dofs());
  for (int a = 0; a < m.num_nodes(); ++a) u.segment<2>(2 * a) = cubic.u(m.nodes[a]);
  return error_norms(m, Material(1.3, 0.3), u, cubic);
}
}  // namespace

// The interpolant of a quadratic field is the field: no error, on the jittered mesh too.
TEST(P2Errors, interpolant_of_a_quadratic_field_has_zero_error) {
  const Mesh m = jittered_p2_rectangle();
  Quadratic u;
  u.c << 0.1, 0.3, -0.2, 0.5, -0.7, 0.2, -0.3, 0.4, 0.6, -0.1, 0.25, 0.8;
  const ErrorNorms e = error_norms(m, Material(1.7, 0.3), u.nodal(m), exact_solution(u));
  EXPECT_GT(e.exact.l2, 0.1);
  EXPECT_LT(e.relative_l2(), 1e-13);
  EXPECT_LT(e.relative_energy(), 1e-13);
}

// For a cubic field the interpolation error falls as h^2 in energy and h^3 in L2: halving h
// divides them by about 4 and 8.
TEST(P2Errors, interpolant_of_a_cubic_field_converges_at_rates_2_and_3) {
  const ErrorNorms coarse = cubic_interpolation_error(8), fine = cubic_interpolation_error(16);
  const double energy_ratio = coarse.relative_energy() / fine.relative_energy();
  const double l2_ratio = coarse.relative_l2() / fine.relative_l2();
  std::printf("P2 interpolant of a cubic, h -> h/2 (8 -> 16 cells): energy ratio %.6f, L2 ratio %.6f\n",
              energy_ratio, l2_ratio);
  EXPECT_GT(energy_ratio, 3.6);
  EXPECT_LT(energy_ratio, 4.4);
  EXPECT_GT(l2_ratio, 7.0);
  EXPECT_LT(l2_ratio, 9.0);
}

// A linear field has constant strain: the stress of every triangle is C eps.
TEST(P2Stresses, linear_field_gives_C_eps_in_every_triangle) {
  const Mesh m = jittered_p2_rectangle();
  const Material material(2.1, 0.25);
  Quadratic u;
  u.c << 0.1, 0.3, -0.2, 0, 0, 0, -0.3, 0.4, 0.6, 0, 0, 0;
  const Eigen::Vector3d sigma = material.voigt() * u.strain(Eigen::Vector2d::Zero());
  const std::vector<Eigen::Vector3d> stress = element_stresses(m, material, u.nodal(m));
  ASSERT_EQ(stress.size(), m.triangles.size());
  for (const Eigen::Vector3d& s : stress) EXPECT_LT((s - sigma).norm(), 1e-13 * sigma.norm());
}
