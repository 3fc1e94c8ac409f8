#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "exercise.hpp"

namespace {
// The node's equations, written here once more, and the Newton step from a derivative by
// central differences: what newton_step must reproduce wherever v is away from a kink.
Eigen::Vector2d equations(const Eigen::Matrix2d& A, const Eigen::Vector2d& r, double F, const Eigen::Vector2d& v) {
  const Eigen::Vector2d l = r - A * v;
  const double g = l[0] + A(0, 0) * v[0];
  if (g <= 0) return l;
  const double s = F * g, z = l[1] + A(1, 1) * v[1];
  return {l[0] - g, std::max(s, std::fabs(z)) * l[1] - s * z};
}

Eigen::Vector2d difference_step(const Eigen::Matrix2d& A, const Eigen::Vector2d& r, double F, const Eigen::Vector2d& v) {
  const double h = 1e-7;
  Eigen::Matrix2d J;
  for (int k = 0; k < 2; ++k) {
    Eigen::Vector2d e = Eigen::Vector2d::Zero();
    e[k] = h;
    J.col(k) = (equations(A, r, F, v + e) - equations(A, r, F, v - e)) / (2 * h);
  }
  return v - J.partialPivLu().solve(equations(A, r, F, v));
}

const Eigen::Matrix2d A = (Eigen::Matrix2d() << 4.0, 0.5, 0.5, 3.0).finished();
}  // namespace

TEST(FrictionNewtonStep, one_step_is_newtons_step_in_each_status) {
  struct Case {
    Eigen::Vector2d r, v;
    const char* what;
  };
  const Case cases[] = {
      {{1.0, 0.1}, {-0.01, 0.02}, "closed, stuck, moving a little"},
      {{1.0, 1.0}, {0.02, 0.1}, "closed, slipping forwards"},
      {{1.0, -1.0}, {-0.03, -0.2}, "closed, slipping backwards"},
      {{1.0, 1.0}, {0.0, -0.2}, "closed, slipping against the shear"},
      {{-1.0, 0.2}, {-0.5, 0.3}, "open"},
  };
  for (const Case& c : cases) {
    const Eigen::Vector2d mine = exercise::newton_step(A, c.r, 0.3, c.v);
    const Eigen::Vector2d reference = difference_step(A, c.r, 0.3, c.v);
    EXPECT_LT((mine - reference).norm(), 1e-6 * (1 + reference.norm())) << c.what << ": got " << mine.transpose()
                                                                          << ", expected " << reference.transpose();
  }
}

// Worked by hand, A = (4 0.5; 0.5 3), F = 0.3, c_n = 4, c_t = 3 (and checked with a Newton step
// from central differences in a separate script). Both first steps keep w_n = 0, since C_n = -4 w_n.
//  - Slipping, r = (1, 1), v = 0: lambda = (1, 1), s = 0.3, z = 1 > s. C = (0, |z| lambda_t - s z) =
//    (0, 0.7). With d lambda / dv = -A: dz/dv = (-0.5, 0), ds/dv = F (-A(0, :) + (c_n, 0)) = (0, -0.15),
//    dC_t/dv = sign(z) lambda_t dz/dv - |z| A(1, :) - z ds/dv - s dz/dv = (-0.85, -2.85), J = (-4 0; -0.85 -2.85),
//    so v+ = (0, 0.7 / 2.85). With s held constant it would be (0, 0.7 / 3).
//  - Stuck, r = (1, 0.1), v = (0, 0.02): lambda = (0.99, 0.04), s = 0.297, z = 0.1 < s. On the stick
//    side C_t = -s c_t w_t with s = F (r_n - A(0, 1) w_t), so C_t = -0.9 w_t (1 - 0.5 w_t) along w_n = 0,
//    dC_t/dw_t = -0.9 (1 - w_t) = -0.882, and w_t+ = w_t - C_t / C_t' = -0.5 w_t^2 / (1 - w_t) = -1/4900.
//    With s held constant it would be exactly 0.
TEST(FrictionNewtonStep, two_first_steps_worked_by_hand) {
  const Eigen::Vector2d slipping = exercise::newton_step(A, Eigen::Vector2d(1.0, 1.0), 0.3, Eigen::Vector2d(0.0, 0.0));
  EXPECT_LT((slipping - Eigen::Vector2d(0.0, 0.7 / 2.85)).norm(), 1e-14) << "slipping: got " << slipping.transpose();
  const Eigen::Vector2d stuck = exercise::newton_step(A, Eigen::Vector2d(1.0, 0.1), 0.3, Eigen::Vector2d(0.0, 0.02));
  EXPECT_LT((stuck - Eigen::Vector2d(0.0, -1.0 / 4900)).norm(), 1e-14) << "stuck: got " << stuck.transpose();
}

TEST(FrictionNewtonStep, your_steps_solve_the_node_in_each_case) {
  // stick, slip (w_t = 0.7 / 2.85 from 1 - 3 w_t = 0.3 (1 - 0.5 w_t)) and open, from v = 0
  struct Case {
    Eigen::Vector2d r, answer;
  };
  const Case cases[] = {{{1.0, 0.1}, {0.0, 0.0}},
                        {{1.0, 1.0}, {0.0, 0.7 / 2.85}},
                        {{-1.0, 0.2}, A.partialPivLu().solve(Eigen::Vector2d(-1.0, 0.2))}};
  for (const Case& c : cases) {
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    for (int step = 0; step < 20 && equations(A, c.r, 0.3, v).norm() > 1e-14; ++step) v = exercise::newton_step(A, c.r, 0.3, v);
    EXPECT_LT((v - c.answer).norm(), 1e-12) << "r = " << c.r.transpose() << ": got " << v.transpose();
  }
}
