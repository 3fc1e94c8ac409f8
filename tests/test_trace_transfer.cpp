#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/interface/trace_transfer.hpp"

using namespace mortar;

namespace {
MortarMatrices build(const InterfaceTrace& t1, const InterfaceTrace& t2) {
  return mortar_matrices(t1, t2, merge_traces(t1, t2), end_modified_p1(t1));
}
}  // namespace

TEST(TraceTransfer, mortar_projection_reproduces_every_p1_function_of_side_1) {
  // Side 2 refines side 1 (3 sub-elements each, jittered inside), so every P1 function of
  // side 1 is also one of side 2: the projection must give it back exactly.
  const InterfaceTrace t1 = uniform_trace(1.0, 7, 0.4, 9);
  InterfaceTrace t2;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.2, 0.45);
  for (int e = 0; e < t1.num_elements(); ++e) {
    const double a = t1.x[e], b = t1.x[e + 1];
    t2.x.insert(t2.x.end(), {a, a + u(rng) * (b - a), b - u(rng) * (b - a)});
  }
  t2.x.push_back(1.0);
  t2.nodes.assign(t2.x.size(), -1);
  const MortarMatrices m = build(t1, t2);
  std::normal_distribution<double> n(0, 1);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> w1(t1.num_nodes());
    for (double& v : w1) v = n(rng);
    std::vector<double> w2;
    for (double x : t2.x) w2.push_back(t1.evaluate(w1, x));
    const std::vector<double> back = mortar_projection(t1, t2, m, w2);
    for (int i = 0; i < t1.num_nodes(); ++i) EXPECT_NEAR(back[i], w1[i], 1e-13) << "node " << i;
  }
}

TEST(TraceTransfer, mortar_projection_reproduces_linear_functions_on_nonmatching_grids) {
  const InterfaceTrace t1 = uniform_trace(3.0, 11, 0.4, 1), t2 = uniform_trace(3.0, 7, 0.4, 2);
  std::vector<double> w2;
  for (double x : t2.x) w2.push_back(2 - 0.7 * x);
  const std::vector<double> w1 = mortar_projection(t1, t2, build(t1, t2), w2);
  for (int i = 0; i < t1.num_nodes(); ++i) EXPECT_NEAR(w1[i], 2 - 0.7 * t1.x[i], 1e-13);
}

TEST(TraceTransfer, mortar_projection_conserves_the_integral) {
  std::mt19937 rng(11);
  std::normal_distribution<double> n(1, 1);
  for (auto [n1, n2] : {std::pair{5, 50}, {50, 5}, {17, 23}, {30, 20}}) {
    const InterfaceTrace t1 = uniform_trace(1.0, n1, 0.4, 1), t2 = uniform_trace(1.0, n2, 0.4, 2);
    std::vector<double> w2(t2.num_nodes());
    for (double& v : w2) v = n(rng);
    const std::vector<double> w1 = mortar_projection(t1, t2, build(t1, t2), w2);
    EXPECT_NEAR(integral(t1, w1), integral(t2, w2), 1e-13 * std::fabs(integral(t2, w2)))
        << n1 << " / " << n2 << " elements";
  }
}

TEST(TraceTransfer, pointwise_transfer_does_not_conserve_the_integral) {
  const InterfaceTrace t1 = uniform_trace(1.0, 5), t2 = uniform_trace(1.0, 13);
  std::vector<double> w2;
  for (double x : t2.x) w2.push_back(1 + std::fabs(x - 0.41));
  const std::vector<double> w1 = pointwise_transfer(t1, t2, w2);
  EXPECT_GT(std::fabs(integral(t1, w1) - integral(t2, w2)), 1e-3);
  for (int i = 0; i < t1.num_nodes(); ++i) EXPECT_DOUBLE_EQ(w1[i], t2.evaluate(w2, t1.x[i]));
}

TEST(TraceTransfer, mortar_projection_refuses_a_single_side1_element) {
  // Both nodes of a single element are end nodes: nothing is left to keep int w.
  const InterfaceTrace t1 = uniform_trace(1.0, 1), t2 = uniform_trace(1.0, 5);
  const std::vector<double> w2 = {0, 1, 0, 1, 0, 1};
  EXPECT_THROW(mortar_projection(t1, t2, build(t1, t2), w2), std::invalid_argument);
}
