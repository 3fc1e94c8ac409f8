#include "level.hpp"

namespace chapter03 {

mortar::BilateralSolution solve_pointwise_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                   const mortar::BilateralOptions& options) {
  // 1. The two meshed bodies and K: one P1 stiffness per body, block diagonal in the global
  //    numbering, because the bodies only meet through B.
  const mortar::SparseMatrix K = bodies.stiffness();

  // 2. Gamma_c seen from both bodies: the non-mortar trace, whose nodes xi^1 carry the rows,
  //    and the mortar trace xi^2. Their nodes do not match.
  mortar::BilateralSolution s(mortar::contact_traces(bodies, options.nonmortar));

  // 3. The pointwise rows of B, one per node a of xi^1: u^1(a).n^1 + u^2(a).n^2 = 0, with
  //    u^2(a) interpolated from the two mortar hats around x_a. This is the space V_h^P
  //    (paper section 3). Rows on prescribed dofs only are dropped.
  s.constraints = mortar::constraint_rows(bodies, s.gamma, mortar::pointwise_matching_rows(s.gamma),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 4. Dirichlet elimination: the prescribed dofs leave K, their values move to the right.
  const mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, scene.F, scene.dirichlet);

  // 5. The saddle point [K B^T; B 0] (u, lambda) = (f, 0): u_h in V_h^P and one multiplier
  //    lambda_a per node a, a nodal force, not a pressure.
  mortar::solve_saddle_point(system, options, s);

  // 6. What they say on Gamma_c. Not part of the method, only of measuring it: the merged grid
  //    of both traces, on which [u_h.n] is P1 (chapter 1), and chapter 4's M_h^1, in which the
  //    study takes the best approximation of the pressure. The pressure is lambda_a over the
  //    tributary length of a (common/contact/contact_fields.hpp).
  s.gamma.grid = mortar::merge_traces(s.gamma.nonmortar_trace, s.gamma.mortar_trace);
  s.gamma.space = mortar::end_modified_p1(s.gamma.nonmortar_trace);
  s.pressure = mortar::contact_pressure(s.gamma, s.constraints, s.lambda);
  s.jump = mortar::normal_jump(bodies, s.gamma, s.u);
  return s;
}

}  // namespace chapter03
