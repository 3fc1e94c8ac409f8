#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <stdexcept>

#include "common/fem/p1_elasticity.hpp"
#include "exercise.hpp"

namespace {
using Matrix6 = Eigen::Matrix<double, 6, 6>;

const std::array<Eigen::Vector2d, 3> triangle = {Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(1.3, 0.15),
                                                 Eigen::Vector2d(0.4, 0.9)};

// The nodal values on `x` of the affine field (a x + b y, c x + d y).
Eigen::Matrix<double, 6, 1> affine_field(const std::array<Eigen::Vector2d, 3>& x, double a, double b, double c,
                                         double d) {
  Eigen::Matrix<double, 6, 1> u;
  for (int k = 0; k < 3; ++k) u.segment<2>(2 * k) << a * x[k].x() + b * x[k].y(), c * x[k].x() + d * x[k].y();
  return u;
}
}  // namespace

// Worked by hand (and again in exact rational arithmetic): on (0,0), (1,0), (0,1) the
// barycentric gradients are (-1,-1), (1,0), (0,1) and |T| = 1/2; E = 1, nu = 0 gives
// lambda = 0, mu = 1/2, so the Voigt C is diag(1, 1, 1/2), and 4 K_T is the integer matrix below.
TEST(P1ElementMatrix, matches_the_unit_triangle_worked_by_hand) {
  const std::array<Eigen::Vector2d, 3> unit = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)};
  Matrix6 four_K;
  four_K << 3, 1, -2, -1, -1, 0,
            1, 3, 0, -1, -1, -2,
            -2, 0, 2, 0, 0, 0,
            -1, -1, 0, 1, 1, 0,
            -1, -1, 0, 1, 1, 0,
            0, -2, 0, 0, 0, 2;
  const Matrix6 K = exercise::element_stiffness(unit, 1.0, 0.0);
  EXPECT_LT((K - 0.25 * four_K).cwiseAbs().maxCoeff(), 1e-14) << "K_T =\n" << K;
}

// u^T K_T u = |T| sigma(u) : eps(u) for an affine u. On `triangle`, |T| = 243/400 = 0.6075; with
// E = 2, nu = 0.3 the Lame coefficients are lambda = 15/13, mu = 10/13. u = (x, 0) has the Voigt
// strain (1, 0, 0): |T| (lambda + 2 mu) = 1701/1040. u = (y, 0) has (0, 0, 1), a pure shear:
// |T| mu = 243/520. (By hand, and checked in exact rational arithmetic.)
TEST(P1ElementMatrix, gives_the_energy_of_two_affine_fields_worked_by_hand) {
  const Matrix6 K = exercise::element_stiffness(triangle, 2.0, 0.3);
  const auto stretch = affine_field(triangle, 1, 0, 0, 0), shear = affine_field(triangle, 0, 1, 0, 0);
  EXPECT_NEAR(stretch.dot(K * stretch), 1701.0 / 1040, 1e-13) << "u = (x, 0)";
  EXPECT_NEAR(shear.dot(K * shear), 243.0 / 520, 1e-13) << "u = (y, 0)";
}

TEST(P1ElementMatrix, equals_the_library_matrix) {
  for (double nu : {0.0, 0.3, 0.45}) {
    const auto K = exercise::element_stiffness(triangle, 2.0, nu);
    const auto reference = mortar::element_stiffness(triangle, mortar::Material(2.0, nu));
    EXPECT_LT((K - reference).norm(), 1e-13 * reference.norm()) << "nu = " << nu;
  }
}

TEST(P1ElementMatrix, has_exactly_three_rigid_modes) {
  const auto K = exercise::element_stiffness(triangle, 1.0, 0.3);
  const Eigen::SelfAdjointEigenSolver<Matrix6> eig(K);
  const double tol = 1e-12 * eig.eigenvalues().cwiseAbs().maxCoeff();
  int zero = 0;
  for (int i = 0; i < 6; ++i) zero += std::abs(eig.eigenvalues()[i]) < tol;
  EXPECT_EQ(zero, 3);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -tol);
}

// The library refuses clockwise vertices; the same triangle listed in any order is the same
// element, so K_T must be the counter-clockwise one with its unknowns permuted.
TEST(P1ElementMatrix, does_not_depend_on_the_order_of_the_vertices) {
  const Matrix6 reference = mortar::element_stiffness(triangle, mortar::Material(2.0, 0.3));  // counter-clockwise
  std::array<int, 3> order = {0, 1, 2};
  do {
    const std::array<Eigen::Vector2d, 3> x = {triangle[order[0]], triangle[order[1]], triangle[order[2]]};
    const Matrix6 K = exercise::element_stiffness(x, 2.0, 0.3);
    // vertex a of x is vertex order[a] of the triangle
    Matrix6 expected;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) expected(a, b) = reference(2 * order[a / 2] + a % 2, 2 * order[b / 2] + b % 2);
    EXPECT_LT((K - expected).norm(), 1e-13 * reference.norm())
        << "vertices in the order " << order[0] << order[1] << order[2] << ", K_T =\n" << K;
  } while (std::next_permutation(order.begin(), order.end()));
}

TEST(P1ElementMatrix, refuses_a_flat_triangle_and_an_impossible_material) {
  const std::array<Eigen::Vector2d, 3> collinear = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(3, 3)};
  const std::array<Eigen::Vector2d, 3> repeated = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 0)};
  EXPECT_THROW(exercise::element_stiffness(collinear, 1.0, 0.3), std::invalid_argument);
  EXPECT_THROW(exercise::element_stiffness(repeated, 1.0, 0.3), std::invalid_argument);
  EXPECT_THROW(exercise::element_stiffness(triangle, 0.0, 0.3), std::invalid_argument);
  EXPECT_THROW(exercise::element_stiffness(triangle, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(exercise::element_stiffness(triangle, 1.0, -1.0), std::invalid_argument);
}
