#include "level.hpp"

#include "common/study/stopwatch.hpp"

namespace chapter04 {

mortar::BilateralSolution solve_integral_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                  const mortar::BilateralOptions& options) {
  mortar::BilateralSolution s;
  const mortar::Stopwatch clock;

  // 1. Gamma_c seen from both bodies: the non-mortar trace (nodes xi^1, it carries the
  //    multipliers) and the mortar trace (nodes xi^2). The two sets of nodes do not match.
  mortar::ContactInterface& gamma = s.gamma;
  gamma = mortar::contact_traces(bodies, options.nonmortar);

  // 2. The merged grid: the union of both traces' nodes. On each of its segments both traces
  //    are linear, so products of their hats integrate exactly there (chapter 1).
  gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);

  // 3. The multiplier space M_h^1 on the non-mortar trace: the P1 hats psi_i of the interior
  //    nodes, constant on the two end elements (paper, section 3).
  gamma.space = mortar::end_modified_p1(gamma.nonmortar_trace);

  // 4. The mortar matrices D_ij = int psi_i phi^1_j and M_ik = int psi_i phi^2_k, exact on the
  //    merged grid.
  gamma.matrices = mortar::mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);

  // 5. The rows of B, one per psi_i: int psi_i [u_h.n] = sum_j D_ij u^1_j.n^1 + sum_k M_ik u^2_k.n^2
  //    = 0, the weak matching that defines V_h^I. Rows on prescribed dofs only are dropped.
  s.constraints = mortar::constraint_rows(bodies, gamma, mortar::Matching::integral,
                                          mortar::integral_matching_rows(gamma),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 6. The saddle point [K B^T; B 0] (u, lambda) = (f, 0): K of both bodies, Dirichlet dofs
  //    eliminated, then lambda_h, the contact pressure, comes out with u_h.
  mortar::SaddlePointSolution x =
      mortar::solve_glued_bodies(bodies, scene, s.constraints, options.solver, options.backend);
  s.u = std::move(x.u);
  s.lambda = std::move(x.lambda);
  s.time_s = clock.seconds();
  return s;
}

}  // namespace chapter04
