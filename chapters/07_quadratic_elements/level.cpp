#include "level.hpp"

#include "common/contact/contact_fields.hpp"

namespace chapter07 {

mortar::BilateralSolution solve_quadratic(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                          const mortar::BilateralOptions& options) {
  // 1. K: one P2 stiffness per body (12 x 12 element matrices, exact by a degree-2 triangle
  //    rule), block diagonal in the global numbering.
  const mortar::SparseMatrix K = bodies.stiffness();

  // 2. Gamma_c seen from both bodies: each trace is quadratic on every element, with 2N + 1
  //    nodes, the end points and midpoints of its N elements.
  mortar::BilateralSolution s(mortar::contact_traces(bodies, options.nonmortar));
  mortar::ContactInterface& gamma = s.gamma;

  // 3. The merged grid: the union of the element end points of both traces (the midpoints add
  //    no breakpoint: each trace is one quadratic on each of its elements).
  gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);

  // 4. M_h^1 for q = 2 (paper section 3): continuous P2 on T_c^1, P1 on the two end elements.
  gamma.space = mortar::end_modified_p2(gamma.nonmortar_trace);

  // 5. D and M: on a merged segment psi_i, phi^1_j and phi^2_k are quadratics, their products
  //    quartics, which 3-point Gauss integrates exactly.
  gamma.matrices = mortar::mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);

  // 6. The rows of B: pointwise, [u_h.n](a) = 0 at every node a of xi^1, midpoints included
  //    (V_h^P); integral, int psi_i [u_h.n] = 0 for every psi_i of M_h^1 (V_h^I).
  s.constraints = mortar::constraint_rows(bodies, gamma, mortar::matching_rows(gamma, options.matching),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 7. Dirichlet elimination, then the saddle point [K B^T; B 0] (u, lambda) = (f, 0), paper (8).
  mortar::solve_saddle_point(mortar::eliminate_dirichlet(K, scene.F, scene.dirichlet), options, s);

  // 8. On Gamma_c: the pressure (lambda_h, quadratic on xi^1; for pointwise matching the nodal
  //    forces over int phi_a) and the jump [u_h.n], quadratic on each merged segment.
  s.pressure = mortar::contact_pressure(gamma, s.constraints, s.lambda);
  s.jump = mortar::normal_jump(bodies, gamma, s.u);
  return s;
}

}  // namespace chapter07
