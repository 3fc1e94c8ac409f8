// Bilateral contact (chapters 3 and 4): what one solve produces, its saddle-point step, and
// the whole solve for either matching, built from the same named steps as the chapters'
// level.cpp (the traces, the rows of B, Dirichlet elimination, the saddle point, the pressure
// and the jump on Gamma_c).
#pragma once

#include <utility>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/contact/saddle_point.hpp"
#include "common/fem/dirichlet.hpp"

namespace mortar {

struct BilateralOptions {
  Matching matching = Matching::integral;  // read by solve_bilateral only
  int nonmortar = 0;  // body index of the non-mortar side
  SaddleSolver solver = SaddleSolver::elimination;
  SpdBackend backend = fastest_spd_backend();
};

struct BilateralSolution {
  BilateralSolution() = default;
  // A solve starts from Gamma_c seen from both bodies (contact_traces or make_interface).
  explicit BilateralSolution(ContactInterface traces) : gamma(std::move(traces)) {}

  ContactInterface gamma;
  Constraints constraints;
  Eigen::VectorXd u;       // both bodies, full (prescribed dofs included)
  Eigen::VectorXd lambda;  // one multiplier per kept constraint row
  // What (u_h, lambda_h) says on Gamma_c: the pressure at the non-mortar nodes and the normal
  // jump [u_h.n] at the merged-grid nodes (contact_fields.hpp).
  InterfaceCurve pressure, jump;
};

// The saddle-point step, once K is reduced to the free dofs (system) and s.constraints holds
// B: solves [K B^T; B 0] (u, lambda) = (f, 0) on the free dofs (the prescribed values of the
// rows' dofs move to the right-hand side, G = -B u_d) and puts s.u on every dof, s.lambda.
void solve_saddle_point(const ReducedSystem& system, const BilateralOptions& options, BilateralSolution& s);

// One whole bilateral solve for options.matching: K, make_interface, build_constraints,
// Dirichlet elimination, the saddle point, the pressure and the jump. Chapters 3 and 4 take
// these steps one by one in their level.cpp; tests and chapter 5 call this.
BilateralSolution solve_bilateral(const TwoBodies& bodies, const SceneData& scene,
                                  const BilateralOptions& options);

// The physical limit of a two-body level (README.md, "Speed"): assemble K of both bodies,
// eliminate the Dirichlet dofs, one Cholesky factorization and one solve; the scene must
// hold each body. two_body_limit_matrix is that K (for time_against_limit).
SparseMatrix two_body_limit_matrix(const TwoBodies& bodies, const SceneData& scene);
double two_body_limit(const TwoBodies& bodies, const SceneData& scene);

}  // namespace mortar
