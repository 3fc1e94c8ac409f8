#include "level.hpp"

#include "common/study/stopwatch.hpp"

namespace chapter03 {

mortar::BilateralSolution solve_pointwise_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                   const mortar::BilateralOptions& options) {
  mortar::BilateralSolution s;
  const mortar::Stopwatch clock;

  // 1. Gamma_c seen from both bodies: the non-mortar trace, whose nodes xi^1 carry the rows,
  //    and the mortar trace (nodes xi^2). The two sets of nodes do not match.
  mortar::ContactInterface& gamma = s.gamma;
  gamma = mortar::contact_traces(bodies, options.nonmortar);

  // 2. The pointwise rows, one per node a of xi^1: the normal displacements agree there,
  //    u^1(a).n^1 + u^2(a).n^2 = 0, with u^2(a) interpolated from the two mortar hats around x_a.
  //    This is the space V_h^P of the paper (section 3). Rows on prescribed dofs are dropped.
  s.constraints = mortar::constraint_rows(bodies, gamma, mortar::Matching::pointwise,
                                          mortar::pointwise_matching_rows(gamma),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 3. The saddle point [K B^T; B 0] (u, lambda) = (f, 0): K of both bodies, Dirichlet dofs
  //    eliminated. lambda_a is a nodal force at a, not a pressure (README.md, "Errors").
  mortar::SaddlePointSolution x =
      mortar::solve_glued_bodies(bodies, scene, s.constraints, options.solver, options.backend);
  s.u = std::move(x.u);
  s.lambda = std::move(x.lambda);
  s.time_s = clock.seconds();

  // 4. Not part of the method, but for measuring it afterwards: the merged grid of both traces,
  //    on which [u_h.n] is piecewise linear (chapter 1), and M_h^1, in which the best
  //    approximation of the pressure is taken (chapter 4). Outside the timed solve.
  gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);
  gamma.space = mortar::end_modified_p1(gamma.nonmortar_trace);
  return s;
}

}  // namespace chapter03
