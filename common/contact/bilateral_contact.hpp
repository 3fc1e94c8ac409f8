// One bilateral contact solve (chapters 3 and 4): Gamma_c, the constraint rows of the chosen
// matching, Dirichlet elimination, the saddle-point solve, timed as one piece.
#pragma once

#include "common/contact/constraints.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/contact/saddle_point.hpp"

namespace mortar {

struct BilateralOptions {
  Matching matching = Matching::integral;
  int nonmortar = 0;  // body index of the non-mortar side
  SaddleSolver solver = SaddleSolver::elimination;
  SpdBackend backend = fastest_spd_backend();
};

struct BilateralSolution {
  ContactInterface gamma;
  Constraints constraints;
  Eigen::VectorXd u;       // both bodies, full (prescribed dofs included)
  Eigen::VectorXd lambda;  // one multiplier per kept constraint row
  double time_s = 0;       // assembly of K and B, Dirichlet elimination, solve
};

BilateralSolution solve_bilateral(const TwoBodies& bodies, const SceneData& scene,
                                  const BilateralOptions& options);

// The last step of one bilateral solve, once B is known: assemble K of both bodies, move the
// Dirichlet dofs into the right-hand side, solve the saddle point [K B^T; B 0] (u, lambda) =
// (f, 0) on the free dofs and put the prescribed values back into u (all dofs).
SaddlePointSolution solve_glued_bodies(const TwoBodies& bodies, const SceneData& scene,
                                       const Constraints& constraints, SaddleSolver solver,
                                       SpdBackend backend = fastest_spd_backend());

// The physical limit of a two-body level (README.md, "Speed"): assemble K of both bodies,
// eliminate the Dirichlet dofs, one Cholesky factorization and one solve; the scene must
// hold each body.
double two_body_limit(const TwoBodies& bodies, const SceneData& scene);

}  // namespace mortar
