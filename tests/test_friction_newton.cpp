// Frictional contact by the semismooth Newton method (common/contact/friction_newton.hpp):
// a one-node problem solved by hand in each of its cases, zero friction is chapter 6's
// frictionless answer, huge friction is the bodies glued where they touch, Coulomb by the
// fixed point on Tresca thresholds is the same answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/contact/bilateral_contact.hpp"
#include "common/contact/friction_newton.hpp"
#include "common/contact/manufactured_friction.hpp"
#include "common/interface/dual_basis.hpp"

using namespace mortar;

namespace {
// One node, two unknowns v = (w_n, w_t): lambda = r - A v with A = [k_n k_c; k_c k_t].
CondensedContact one_node(double r_n, double r_t) {
  CondensedContact c;
  c.pivots = {0, 1};
  c.b = Eigen::VectorXd::Ones(2);
  c.Z.resize(2, 2);  // T = I: row s_i of T is e_i
  c.Z.setIdentity();
  c.g = Eigen::VectorXd::Zero(2);
  std::vector<Eigen::Triplet<double>> t{{0, 0, 4.0}, {0, 1, 0.5}, {1, 0, 0.5}, {1, 1, 3.0}};
  c.A.resize(2, 2);
  c.A.setFromTriplets(t.begin(), t.end());
  c.rhs = Eigen::Vector2d(r_n, r_t);
  return c;
}

FrictionOptions coulomb(double F) {
  FrictionOptions o;
  o.law = FrictionLaw::coulomb;
  o.friction = F;
  return o;
}

struct Problem {
  TwoBodies bodies;
  SaddlePointProblem normal, frictional;
  std::vector<int> row_node;
};

// Chapter 5's Hertz-like scene on the dual basis: two blocks pressed by delta over the gap
// (x - 1/2)^2 / 2, materials E1 = 1 and E2 (E2 != E1: the normal load alone makes a shear).
Problem pressed(int n1, double ratio, double E2, double delta = 0.02, double E1 = 1) {
  TwoBodyGeometry g;
  g.n1 = g.m1 = n1;
  g.n2 = g.m2 = std::max(2, static_cast<int>(std::lround(n1 / ratio)));
  g.H1 = g.H2 = 1;
  g.jitter = 0.2;
  TwoBodies bodies = make_two_bodies(g, Material(E1, 0.3), Material(E2, 0.3));
  const SceneData scene = pressed_between_plates(bodies, delta);
  const std::vector<bool> mask = scene.prescribed_mask(bodies.num_dofs());
  const ContactInterface gamma = make_dual_interface(bodies, 0);
  const MatchingRows rows = integral_matching_rows(gamma);
  const Constraints cn = constraint_rows(bodies, gamma, rows, mask);
  const Constraints ct = tangential_constraint_rows(bodies, gamma, rows, mask);
  const Eigen::VectorXd G = tested_gap(gamma, cn, [](double x) { return (x - 0.5) * (x - 0.5) / 2; });
  const ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  const SaddlePointProblem normal = reduce_to_free_dofs(system, cn, G);
  const SaddlePointProblem tangential = reduce_to_free_dofs(system, ct, Eigen::VectorXd::Zero(ct.B.rows()));
  return {std::move(bodies), normal, stack_frictional_rows(normal, tangential), cn.row_node};
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }
}  // namespace

TEST(FrictionNewton, one_node_sticks_when_the_shear_is_below_the_threshold) {
  const FrictionSolution x = solve_frictional_contact(one_node(1.0, 0.1), coulomb(0.3));
  ASSERT_EQ(x.status[0], NodeStatus::stick);
  EXPECT_NEAR(x.w_n[0], 0.0, 1e-15);
  EXPECT_NEAR(x.w_t[0], 0.0, 1e-15);
  EXPECT_NEAR(x.lambda_n[0], 1.0, 1e-14);
  EXPECT_NEAR(x.lambda_t[0], 0.1, 1e-14);
}

TEST(FrictionNewton, one_node_slips_with_the_coulomb_shear_and_the_step_is_nonsymmetric) {
  // closed (w_n = 0) and slipping: 1 - 3 w_t = 0.3 (1 - 0.5 w_t), w_t = 0.7 / 2.85
  const FrictionSolution x = solve_frictional_contact(one_node(1.0, 1.0), coulomb(0.3));
  ASSERT_EQ(x.status[0], NodeStatus::slip);
  const double w_t = 0.7 / 2.85;
  EXPECT_NEAR(x.w_t[0], w_t, 1e-14);
  EXPECT_NEAR(x.lambda_n[0], 1 - 0.5 * w_t, 1e-14);
  EXPECT_NEAR(x.lambda_t[0], 0.3 * (1 - 0.5 * w_t), 1e-14);
  EXPECT_GE(x.lu_steps, 1);
  // Tresca with s = 0.5: lambda_t = 0.5, w_t = (1 - 0.5) / 3, every step symmetric
  FrictionOptions t;
  t.law = FrictionLaw::tresca;
  t.threshold = Eigen::VectorXd::Constant(1, 0.5);
  const FrictionSolution y = solve_frictional_contact(one_node(1.0, 1.0), t);
  EXPECT_NEAR(y.lambda_t[0], 0.5, 1e-14);
  EXPECT_NEAR(y.w_t[0], 0.5 / 3, 1e-14);
  EXPECT_EQ(y.lu_steps, 0);
}

TEST(FrictionNewton, one_node_pulled_apart_opens_and_carries_nothing) {
  const FrictionSolution x = solve_frictional_contact(one_node(-1.0, 0.2), coulomb(0.3));
  ASSERT_EQ(x.status[0], NodeStatus::open);
  EXPECT_NEAR(x.lambda_n[0], 0.0, 1e-15);
  EXPECT_NEAR(x.lambda_t[0], 0.0, 1e-15);
  EXPECT_NEAR(x.w_n[0], (3 * -1.0 - 0.5 * 0.2) / 11.75, 1e-14);
}

TEST(FrictionNewton, the_slip_of_a_load_step_is_counted_from_the_last_one) {
  // the same node, already slipped by 0.1 before this step: stick keeps w_t = 0.1
  FrictionOptions o = coulomb(0.3);
  o.previous_slip = Eigen::VectorXd::Constant(1, 0.1);
  const FrictionSolution x = solve_frictional_contact(one_node(1.0, 0.4), o);
  // stuck at w_t = 0.1: lambda_t = 0.4 - 0.3 = 0.1, lambda_n = 1 - 0.05 = 0.95, 0.1 < 0.285
  ASSERT_EQ(x.status[0], NodeStatus::stick);
  EXPECT_NEAR(x.w_t[0], 0.1, 1e-15);
  EXPECT_NEAR(x.lambda_t[0], 0.1, 1e-14);
}

TEST(FrictionNewton, zero_friction_is_chapter_6s_frictionless_answer_to_round_off) {
  for (double ratio : {1.5, 1.0 / 3}) {
    const Problem p = pressed(16, ratio, 3.0);
    CondensedContact frictionless = condense_contact(p.normal);
    const DualContactSolution reference = solve_dual_contact(frictionless, DualContactOptions{});
    const FrictionSolution x = solve_frictional_contact(condense_contact(p.frictional), coulomb(0.0));
    EXPECT_LT(relative(x.u, reference.u), 1e-10) << "h2/h1 = " << ratio;
    EXPECT_LT(relative(x.lambda_n, reference.lambda), 1e-10) << "h2/h1 = " << ratio;
    EXPECT_LT(x.lambda_t.cwiseAbs().maxCoeff(), 1e-12 * x.lambda_n.maxCoeff());
  }
}

TEST(FrictionNewton, huge_friction_glues_the_bodies_where_they_touch) {
  const Problem p = pressed(16, 1.5, 3.0, 0.06);
  const FrictionSolution x = solve_frictional_contact(condense_contact(p.frictional), coulomb(1e8));
  int in_contact = 0;
  for (std::size_t i = 0; i < x.status.size(); ++i) {
    EXPECT_NE(x.status[i], NodeStatus::slip) << "node " << i;
    if (x.status[i] == NodeStatus::stick) ++in_contact;
  }
  ASSERT_GT(in_contact, 3);
  EXPECT_GT(x.lambda_t.cwiseAbs().maxCoeff(), 1e-3 * x.lambda_n.maxCoeff());  // E1 != E2: a shear
  // Reference: the saddle point (one LU) with both rows of exactly those nodes as equalities.
  const Eigen::Index m = p.normal.B.rows();
  std::vector<int> keep;
  for (int i = 0; i < m; ++i)
    if (x.status[i] == NodeStatus::stick) keep.push_back(i);
  SaddlePointProblem glued;
  glued.K = p.frictional.K;
  glued.f = p.frictional.f;
  std::vector<Eigen::Triplet<double>> e;
  glued.G.resize(2 * static_cast<Eigen::Index>(keep.size()));
  const Eigen::SparseMatrix<double, Eigen::RowMajor> B = p.frictional.B;
  for (std::size_t k = 0; k < keep.size(); ++k)
    for (int part = 0; part < 2; ++part) {
      const Eigen::Index row = part * m + keep[k], out = part * static_cast<Eigen::Index>(keep.size()) + k;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it)
        e.emplace_back(out, it.col(), it.value());
      glued.G[out] = p.frictional.G[row];
    }
  glued.B.resize(glued.G.size(), glued.K.cols());
  glued.B.setFromTriplets(e.begin(), e.end());
  const SaddlePointSolution reference = solve_saddle_point_lu(glued);
  EXPECT_LT(relative(x.u, reference.u), 1e-9);
}

// The fixed point stops when the thresholds change by less than 1e-10 of themselves: its answer
// is then Newton's to a few times that, whatever the unit of the multipliers (E1 = 1e-3 here:
// an absolute test on the change would stop far earlier).
TEST(FrictionNewton, coulomb_by_fixed_point_on_tresca_thresholds_is_the_same_answer) {
  const Problem p = pressed(16, 1.5, 3e-3, 0.02, 1e-3);
  const CondensedContact c = condense_contact(p.frictional);
  const FrictionSolution newton = solve_frictional_contact(c, coulomb(0.2));
  const FixedPointSolution fixed = solve_coulomb_by_fixed_point(c, coulomb(0.2));
  EXPECT_LT(relative(fixed.last.u, newton.u), 1e-11);
  EXPECT_GT(fixed.outer, 1);
  int slipping = 0;
  for (NodeStatus s : newton.status) slipping += s == NodeStatus::slip;
  EXPECT_GT(slipping, 0);  // the case has slip, so Coulomb's coupling matters
}

// Chapter 8's manufactured scene with F = 0 is frictionless contact with exact Dirichlet data:
// chapter 6's semismooth Newton method on the normal rows alone must give the same answer.
TEST(FrictionNewton, zero_friction_on_the_manufactured_scene_is_chapter_6s_answer) {
  TwoBodyGeometry g;
  g.n1 = g.m1 = 16;
  g.n2 = g.m2 = 11;
  g.H1 = g.H2 = 0.5;
  g.m1 = 8;
  g.m2 = 6;
  const ManufacturedFriction exact(Material(1, 0.3), Material(3, 0.25), 1.0, 0.0);
  const TwoBodies bodies = make_two_bodies(g, exact.material(0), exact.material(1));
  const SceneData scene = manufactured_scene_all_sides(bodies, exact);
  const std::vector<bool> mask = scene.prescribed_mask(bodies.num_dofs());
  const ContactInterface gamma = make_dual_interface(bodies, 0);
  const MatchingRows rows = integral_matching_rows(gamma);
  const Constraints cn = constraint_rows(bodies, gamma, rows, mask), ct = tangential_constraint_rows(bodies, gamma, rows, mask);
  const ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(cn.B.rows());
  const SaddlePointProblem normal = reduce_to_free_dofs(system, cn, zero);
  CondensedContact frictionless = condense_contact(normal);
  const DualContactSolution reference = solve_dual_contact(frictionless, DualContactOptions{});
  const FrictionSolution x = solve_frictional_contact(
      condense_contact(stack_frictional_rows(normal, reduce_to_free_dofs(system, ct, zero))), coulomb(0.0));
  EXPECT_LT(relative(x.u, reference.u), 1e-10);
  EXPECT_LT(relative(x.lambda_n, reference.lambda), 1e-10);
}

// At convergence every slip node's shear is its threshold to the tolerance relative to that
// threshold, small pressures included: a test scaled by the largest multiplier passed with slip
// nodes near the contact edge still far from their threshold.
TEST(FrictionNewton, every_slip_node_holds_its_own_threshold_at_convergence) {
  const Problem p = pressed(64, 1.5, 3.0, 0.06);
  const FrictionSolution x = solve_frictional_contact(condense_contact(p.frictional), coulomb(0.05));
  int slipping = 0;
  for (std::size_t i = 0; i < x.status.size(); ++i) {
    if (x.status[i] != NodeStatus::slip) continue;
    ++slipping;
    const double s = 0.05 * x.lambda_n[i];
    EXPECT_LT(std::fabs(std::fabs(x.lambda_t[i]) - s), 1e-10 * s) << "node " << i << " of pressure " << x.lambda_n[i];
  }
  ASSERT_GT(slipping, 3);
}

// Nothing in the method may depend on the unit of E: E1 = E2 / 3 = 1e-100, 1 and 1e100 give the
// same displacements, multipliers over E and Newton steps.
TEST(FrictionNewton, the_answer_does_not_depend_on_the_unit_of_E) {
  const Problem unit = pressed(16, 1.5, 3.0);
  const FrictionSolution reference = solve_frictional_contact(condense_contact(unit.frictional), coulomb(0.3));
  for (double E : {1e-100, 1e100}) {
    const Problem p = pressed(16, 1.5, 3.0 * E, 0.02, E);
    const FrictionSolution x = solve_frictional_contact(condense_contact(p.frictional), coulomb(0.3));
    EXPECT_LT(relative(x.u, reference.u), 1e-12) << "E = " << E;
    EXPECT_LT(relative(x.lambda_n / E, reference.lambda_n), 1e-12) << "E = " << E;
    EXPECT_LT(relative(x.lambda_t / E, reference.lambda_t), 1e-12) << "E = " << E;
    EXPECT_EQ(x.steps, reference.steps) << "E = " << E;
  }
}
