#include "level.hpp"

namespace chapter04 {

mortar::BilateralSolution solve_integral_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                  const mortar::BilateralOptions& options) {
  // 1. The two meshed bodies and K: one P1 stiffness per body, block diagonal in the global
  //    numbering, because the bodies only meet through B.
  const mortar::SparseMatrix K = bodies.stiffness();

  // 2. Gamma_c seen from both bodies: the non-mortar trace xi^1 (it carries the multipliers)
  //    and the mortar trace xi^2. Their nodes do not match.
  mortar::BilateralSolution s(mortar::contact_traces(bodies, options.nonmortar));
  mortar::ContactInterface& gamma = s.gamma;

  // 3. The merged grid: the union of the nodes of xi^1 and xi^2. On each of its segments
  //    phi^1_j and phi^2_k are both linear, so their products integrate exactly (chapter 1).
  gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);

  // 4. The multiplier space M_h^1 on xi^1: the P1 hats of the interior nodes, with the two end
  //    hats folded into their neighbours (constant on the end elements, paper section 3).
  gamma.space = mortar::end_modified_p1(gamma.nonmortar_trace);

  // 5. The mortar matrices D_ij = int psi_i phi^1_j and M_ik = int psi_i phi^2_k, by 2-point
  //    Gauss on each merged segment.
  gamma.matrices = mortar::mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);

  // 6. The rows of B, one per psi_i: sum_j D_ij u^1_j.n^1 + sum_k M_ik u^2_k.n^2 = 0, that is
  //    int psi_i [u_h.n] = 0, the space V_h^I. Rows on prescribed dofs only are dropped.
  s.constraints = mortar::constraint_rows(bodies, gamma, mortar::integral_matching_rows(gamma),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 7. Dirichlet elimination: the prescribed dofs leave K, their values move to the right.
  const mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, scene.F, scene.dirichlet);

  // 8. The saddle point [K B^T; B 0] (u, lambda) = (f, 0), paper (8): u_h in V_h^I and the
  //    multipliers lambda_i, the coefficients of lambda_h = sum_i lambda_i psi_i.
  mortar::solve_saddle_point(system, options, s);

  // 9. What they say on Gamma_c: the contact pressure lambda_h, P1 on xi^1, and the jump
  //    [u_h.n] at the merged-grid nodes, small but not zero (only its means against M_h^1 are).
  s.pressure = mortar::contact_pressure(gamma, s.constraints, s.lambda);
  s.jump = mortar::normal_jump(bodies, gamma, s.u);
  return s;
}

}  // namespace chapter04
