// One level of chapter 5: meshes, the scene, B and G of the chosen matching, Dirichlet
// elimination, one contact solve, and what it says on Gamma_c.
#pragma once

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/contact/contact_solvers.hpp"
#include "common/fem/errors.hpp"
#include "common/linalg/physical_limit.hpp"
#include "scenes.hpp"

namespace chapter05 {

struct UnilateralSetup {
  mortar::TwoBodyGeometry geometry;
  mortar::Matching matching = mortar::Matching::integral;
  int nonmortar = 0;  // body index
  mortar::ContactSolverOptions solver;
  SceneParameters scene;
  bool measure_limit = true;  // time the physical limit (one more assembly and Cholesky of K)
  mortar::Repetitions repetitions;  // of the level and its limit, interleaved
  // Chapter 6's method, for the solver comparison: the dual basis (integral matching only),
  // the weighted gap and the semismooth Newton method in the displacements; solver unused.
  bool dual_newton = false;
};

struct UnilateralLevel {
  mortar::TwoBodies bodies;
  mortar::ContactInterface gamma;
  mortar::Constraints constraints;
  mortar::ContactSolution solution;
  Eigen::VectorXd u;  // both bodies, prescribed dofs included
  mortar::InterfaceCurve pressure, jump;
  mortar::ContactZone zone;
  std::function<double(double)> gap;
  double total_force = 0;
  double time_s = 0, limit_s = 0;
  mortar::TimedLevel timing{};  // both, with their spread, phases and memory peaks (measure_limit)
  double h1 = 0, h2 = 0;
  // The largest pointwise violation of (9), max ([u_h.n] - g) over Gamma_c, and where: the
  // integral constraints of K_h^I only bound averages of it, so it can stay positive, by
  // O(h^2) where the gap is smooth, by much more where the zone is narrower than an element.
  double max_penetration = 0, max_penetration_x = 0;
  // Round-off of [u_h.n] - g: 1e-9 of the largest |[u_h.n]| or |g| on Gamma_c. A penetration
  // below it (1.4e-17 m at a pointwise contact node, where [u_h.n] = g is imposed) is none.
  double penetration_round_off = 0;
  bool penetrates() const { return max_penetration > penetration_round_off; }
};

UnilateralLevel solve_unilateral_level(const UnilateralSetup& setup,
                                       const mortar::ExactContact& exact);
// The same on bodies meshed by the caller (setup.geometry is then not used): graded meshes.
UnilateralLevel solve_unilateral_level(mortar::TwoBodies bodies, const UnilateralSetup& setup,
                                       const mortar::ExactContact& exact);

}  // namespace chapter05
