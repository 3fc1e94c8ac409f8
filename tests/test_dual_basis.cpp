#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "common/interface/dual_basis.hpp"
#include "common/interface/trace_transfer.hpp"

using namespace mortar;

namespace {
MortarMatrices build(const InterfaceTrace& t1, const InterfaceTrace& t2, const MultiplierSpace& space) {
  return mortar_matrices(t1, t2, merge_traces(t1, t2), space);
}
MortarMatrices dual(const InterfaceTrace& t1, const InterfaceTrace& t2) {
  return build(t1, t2, dual_end_modified_p1(t1));
}
MortarMatrices standard(const InterfaceTrace& t1, const InterfaceTrace& t2) {
  return build(t1, t2, end_modified_p1(t1));
}

// int phi^1_j from the node coordinates: half the lengths of the elements at node j.
double hat_integral(const InterfaceTrace& t, int j) {
  double sum = 0;
  if (j > 0) sum += 0.5 * (t.x[j] - t.x[j - 1]);
  if (j < t.num_elements()) sum += 0.5 * (t.x[j + 1] - t.x[j]);
  return sum;
}

std::vector<double> sampled(const InterfaceTrace& t, double (*f)(double)) {
  std::vector<double> w;
  for (double x : t.x) w.push_back(f(x));
  return w;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::fabs(a[i] - b[i]));
  return worst;
}

double sin3(double x) { return std::sin(3 * x); }

// The nonmatching pairs: (elements of side 1, of side 2, seed of side 1, seed of side 2).
struct Pair {
  int n1, n2;
  unsigned seed1, seed2;
};
const Pair pairs[] = {{7, 11, 1, 2}, {20, 3, 3, 4}, {3, 20, 5, 6}, {11, 7, 7, 8}};
}  // namespace

TEST(DualBasis, D_is_diagonal_on_nonmatching_traces) {
  for (const Pair& p : pairs) {
    const InterfaceTrace t1 = uniform_trace(1.0, p.n1, 0.3, p.seed1), t2 = uniform_trace(1.0, p.n2, 0.3, p.seed2);
    const MultiplierSpace space = dual_end_modified_p1(t1);
    const MortarMatrices m = build(t1, t2, space);
    EXPECT_LT(d_offdiagonal_max(space, m.D), 1e-13) << p.n1 << " / " << p.n2 << " elements";
  }
}

TEST(DualBasis, D_is_diagonal_on_traces_1e14_apart) {
  const InterfaceTrace t1 = uniform_trace(1.0, 12, 0.3, 4);
  InterfaceTrace t2 = t1;
  for (int i = 1; i + 1 < t2.num_nodes(); ++i) t2.x[i] += 1e-14;
  // the nodes 1e-14 apart are merged: the merged grid is side 1's own
  ASSERT_EQ(static_cast<int>(merge_traces(t1, t2).segments.size()), t1.num_elements());
  const MultiplierSpace space = dual_end_modified_p1(t1);
  const MortarMatrices m = build(t1, t2, space);
  EXPECT_LT(d_offdiagonal_max(space, m.D), 1e-13);
  EXPECT_TRUE(Eigen::MatrixXd(m.M).allFinite());
}

TEST(DualBasis, diagonal_of_D_is_the_integral_of_the_hat) {
  for (const Pair& p : pairs) {
    const InterfaceTrace t1 = uniform_trace(1.0, p.n1, 0.3, p.seed1), t2 = uniform_trace(1.0, p.n2, 0.3, p.seed2);
    const MultiplierSpace space = dual_end_modified_p1(t1);
    const MortarMatrices m = build(t1, t2, space);
    // D_ii = int psi_i phi^1_i = int phi^1_i = (h_{i-1} + h_i) / 2, the end element's h / 2
    // included for psi_1 and psi_{N-1} (psi = 1 there)
    for (int i = 0; i < space.dim(); ++i) {
      const int j = space.node_of(i);
      const double expected = hat_integral(t1, j);
      EXPECT_NEAR(m.D.coeff(i, j), expected, 1e-14 * expected) << p.n1 << " / " << p.n2 << ", psi_" << i + 1;
    }
    // and the end columns: int psi_1 phi_0 = h_0 / 2, int psi_{N-1} phi_N = h_{N-1} / 2
    const int N = t1.num_elements();
    EXPECT_NEAR(m.D.coeff(0, 0), hat_integral(t1, 0), 1e-14 * hat_integral(t1, 0));
    EXPECT_NEAR(m.D.coeff(N - 2, N), hat_integral(t1, N), 1e-14 * hat_integral(t1, N));
  }
}

TEST(DualBasis, the_hats_of_the_standard_basis_give_a_D_far_from_diagonal) {
  // the control: the check above would notice a basis that is not biorthogonal
  for (const Pair& p : pairs) {
    const InterfaceTrace t1 = uniform_trace(1.0, p.n1, 0.3, p.seed1), t2 = uniform_trace(1.0, p.n2, 0.3, p.seed2);
    const MultiplierSpace space = end_modified_p1(t1);
    if (space.dim() < 2) continue;  // one multiplier: nothing off the diagonal
    EXPECT_GT(d_offdiagonal_max(space, standard(t1, t2).D), 0.1) << p.n1 << " / " << p.n2 << " elements";
  }
}

TEST(DualBasis, reproduces_constants_element_by_element) {
  for (int N : {2, 3, 7, 20}) {
    const MultiplierSpace space = dual_end_modified_p1(uniform_trace(1.0, N, 0.3, static_cast<unsigned>(N)));
    ASSERT_FALSE(space.continuous());
    ASSERT_EQ(space.dim(), N - 1);
    const Eigen::MatrixXd E = Eigen::MatrixXd(space.element_coefficients());
    ASSERT_EQ(E.cols(), 2 * N);
    // psi_i|_e = sum_l E(i, 2e + l) phi^e_l and phi^e_0 + phi^e_1 = 1: each column must sum to one
    for (int c = 0; c < 2 * N; ++c)
      EXPECT_NEAR(E.col(c).sum(), 1.0, 1e-15) << "N = " << N << ", element " << c / 2 << ", local hat " << c % 2;
  }
}

TEST(DualBasis, is_one_on_the_end_elements) {
  for (int N : {2, 3, 7}) {
    const Eigen::MatrixXd E = Eigen::MatrixXd(dual_end_modified_p1(uniform_trace(1.0, N, 0.3, 9)).E);
    // psi_1 = 1 on element 0 and psi_{N-1} = 1 on element N - 1, and no other psi lives there
    EXPECT_EQ(E(0, 0), 1.0);
    EXPECT_EQ(E(0, 1), 1.0);
    EXPECT_EQ(E(N - 2, 2 * N - 2), 1.0);
    EXPECT_EQ(E(N - 2, 2 * N - 1), 1.0);
    EXPECT_EQ(E.col(0).cwiseAbs().sum(), 1.0) << "N = " << N;
    EXPECT_EQ(E.col(2 * N - 1).cwiseAbs().sum(), 1.0) << "N = " << N;
  }
}

TEST(DualBasis, element_coefficients_are_2_minus_1_for_every_length) {
  // 3-point Gauss on [0, 1]: exact for the quadratic psi_a phi_b
  const double r = std::sqrt(0.15);
  const double points[3] = {0.5 - r, 0.5, 0.5 + r}, weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  for (double h : {1e-6, 0.01, 0.37, 1.0, 250.0}) {
    const Eigen::Matrix2d A = dual_element_coefficients(h);
    Eigen::Matrix2d expected;
    expected << 2, -1, -1, 2;
    EXPECT_LT((A - expected).cwiseAbs().maxCoeff(), 1e-14) << "h = " << h;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        double sum = 0;  // int_e psi_a phi_b on [0, h]
        for (int q = 0; q < 3; ++q) {
          const double s = points[q], phi[2] = {1 - s, s};
          sum += weights[q] * h * (A(a, 0) * phi[0] + A(a, 1) * phi[1]) * phi[b];
        }
        EXPECT_NEAR(sum, a == b ? h / 2 : 0.0, 1e-14 * h) << "h = " << h << ", a = " << a << ", b = " << b;
      }
  }
}

TEST(DualBasis, projection_is_solved_node_by_node) {
  for (const Pair& p : pairs) {
    const InterfaceTrace t1 = uniform_trace(1.0, p.n1, 0.3, p.seed1), t2 = uniform_trace(1.0, p.n2, 0.3, p.seed2);
    const MultiplierSpace space = dual_end_modified_p1(t1);
    const MortarMatrices m = build(t1, t2, space);
    const std::vector<double> w2 = sampled(t2, sin3);
    const std::vector<double> general = mortar_projection(t1, t2, m, w2);
    // D diagonal: w1_j = ((M w2)_i - D_i0 w1_0 - D_iN w1_N) / D_ij, j = node_of(i), the ends from side 2
    const int N = t1.num_elements();
    const Eigen::VectorXd Mw2 = m.M * Eigen::Map<const Eigen::VectorXd>(w2.data(), t2.num_nodes());
    std::vector<double> by_hand(t1.num_nodes());
    by_hand.front() = w2.front();
    by_hand.back() = w2.back();
    for (int i = 0; i < space.dim(); ++i) {
      const int j = space.node_of(i);
      by_hand[j] = (Mw2[i] - m.D.coeff(i, 0) * by_hand.front() - m.D.coeff(i, N) * by_hand.back()) / m.D.coeff(i, j);
    }
    EXPECT_LT(max_difference(by_hand, general), 1e-13) << p.n1 << " / " << p.n2 << " elements";
  }
}

TEST(DualBasis, both_projections_reproduce_linear_functions_and_keep_the_integral) {
  std::mt19937 rng(13);
  std::normal_distribution<double> normal(1, 1);
  for (const Pair& p : pairs) {
    const InterfaceTrace t1 = uniform_trace(1.0, p.n1, 0.3, p.seed1), t2 = uniform_trace(1.0, p.n2, 0.3, p.seed2);
    const MortarMatrices bases[2] = {dual(t1, t2), standard(t1, t2)};
    for (int b = 0; b < 2; ++b) {
      const char* name = b == 0 ? "dual" : "standard";
      const std::vector<double> linear = mortar_projection(t1, t2, bases[b], sampled(t2, [](double x) { return 2 - 0.7 * x; }));
      for (int i = 0; i < t1.num_nodes(); ++i)
        EXPECT_NEAR(linear[i], 2 - 0.7 * t1.x[i], 1e-13) << name << ", " << p.n1 << " / " << p.n2 << ", node " << i;
      std::vector<double> w2(t2.num_nodes());
      for (double& v : w2) v = normal(rng);
      const std::vector<double> w1 = mortar_projection(t1, t2, bases[b], w2);
      EXPECT_NEAR(integral(t1, w1), integral(t2, w2), 1e-13 * std::fabs(integral(t2, w2)))
          << name << ", " << p.n1 << " / " << p.n2 << " elements";
    }
  }
}

// The dual basis spans other functions than M_h^1 (its span is discontinuous at the nodes),
// so its projection D^{-1} M asks int (w1 - w2) psi = 0 against another space and is another
// operator than chapter 1's standard projection. Both are second order, so they differ by O(h^2).
TEST(DualBasis, dual_and_standard_projections_differ_by_order_h2) {
  double difference[2];
  for (int level = 0; level < 2; ++level) {
    const int n1 = 24 << level, n2 = 16 << level;  // h2 / h1 = 3/2
    const InterfaceTrace t1 = uniform_trace(1.0, n1), t2 = uniform_trace(1.0, n2);
    const std::vector<double> w2 = sampled(t2, sin3);
    difference[level] = max_difference(mortar_projection(t1, t2, dual(t1, t2), w2),
                                       mortar_projection(t1, t2, standard(t1, t2), w2));
    std::printf("n1 = %d, n2 = %d: max |dual - standard| = %.3e\n", n1, n2, difference[level]);
  }
  const double ratio = difference[0] / difference[1];
  std::printf("ratio %.3f\n", ratio);
  EXPECT_GT(difference[1], 1e-6);  // not the same operator
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
}

TEST(DualBasis, both_projections_are_the_identity_on_matching_traces) {
  const InterfaceTrace t = uniform_trace(1.0, 13, 0.3, 21);
  const std::vector<double> w = sampled(t, sin3);
  EXPECT_LT(max_difference(mortar_projection(t, t, dual(t, t), w), w), 1e-14);
  EXPECT_LT(max_difference(mortar_projection(t, t, standard(t, t), w), w), 1e-14);
}

TEST(DualBasis, coefficients_all_one_give_the_constant_one) {
  const InterfaceTrace t = uniform_trace(2.0, 9, 0.3, 5);
  for (const MultiplierSpace& space : {dual_end_modified_p1(t), end_modified_p1(t)}) {
    const BrokenCurve one = multiplier_function(space, t, Eigen::VectorXd::Ones(space.dim()));
    EXPECT_LT(l2_error(one, [](double) { return 1.0; }), 1e-14) << (space.continuous() ? "standard" : "dual");
    // and the test has teeth: another constant is 1/2 away everywhere
    EXPECT_NEAR(l2_error(one, [](double) { return 1.5; }), 0.5 * std::sqrt(2.0), 1e-14);
  }
}

TEST(DualBasis, nonnegative_coefficients_can_give_a_negative_function) {
  // a narrow bump: lambda_i = p(x_i) >= 0, but 2 lambda_a - lambda_b < 0 next to its top
  const InterfaceTrace t = uniform_trace(1.0, 20, 0.3, 2);
  const auto p = [](double x) { return std::exp(-std::pow((x - 0.5) / 0.04, 2)); };
  const MultiplierSpace dual_space = dual_end_modified_p1(t), hats = end_modified_p1(t);
  Eigen::VectorXd lambda(dual_space.dim());
  for (int i = 0; i < lambda.size(); ++i) lambda[i] = p(t.x[dual_space.node_of(i)]);
  ASSERT_GE(lambda.minCoeff(), 0.0);
  const auto minimum = [](const BrokenCurve& c) {
    return std::min(*std::min_element(c.left.begin(), c.left.end()), *std::min_element(c.right.begin(), c.right.end()));
  };
  // linear on each element: the minimum is at an element end
  EXPECT_LT(minimum(multiplier_function(dual_space, t, lambda)), -0.1);
  EXPECT_GE(minimum(multiplier_function(hats, t, lambda)), 0.0);
}

TEST(DualBasis, refuses_a_single_element) {
  EXPECT_THROW(dual_end_modified_p1(uniform_trace(1.0, 1)), std::invalid_argument);
  EXPECT_NO_THROW(dual_end_modified_p1(uniform_trace(1.0, 2)));
}
