#include "bilateral_level.hpp"

#include "common/contact/dual_condensation.hpp"
#include "common/interface/dual_basis.hpp"

namespace chapter06 {

mortar::BilateralSolution solve_dual_mortar(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                            const mortar::BilateralOptions& options) {
  // 1. K of both bodies, block diagonal, as in chapter 4.
  mortar::SparseMatrix K = bodies.stiffness();

  // 2. Gamma_c from both sides, and the merged grid of the two traces (chapter 1).
  mortar::BilateralSolution s(mortar::contact_traces(bodies, options.nonmortar));
  mortar::ContactInterface& gamma = s.gamma;
  gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);

  // 3. The dual basis: same nodes and dimension as M_h^1, but int psi_i phi^1_j = 0 for i != j
  //    (common/interface/dual_basis.hpp): psi = 2 phi_a - phi_b on interior elements, 1 on the
  //    two end elements.
  gamma.space = mortar::dual_end_modified_p1(gamma.nonmortar_trace);

  // 4. D and M on the merged grid, exactly as in chapter 4: D comes out diagonal (up to the
  //    quadrature's round-off, d_offdiagonal_max), M does not.
  gamma.matrices = mortar::mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);

  // 5. The rows of B: int psi_i [u_h.n] = 0, chapter 4's V_h^I with the dual psi_i. Each row
  //    holds one non-mortar normal dof of an interior node (its pivot) and mortar dofs.
  s.constraints = mortar::constraint_rows(bodies, gamma, mortar::integral_matching_rows(gamma),
                                          scene.prescribed_mask(bodies.num_dofs()));

  // 6. Dirichlet elimination. From here one stiffness matrix at a time is kept (the factor is
  //    the memory peak; Eigen 3.4's SparseMatrix has no move, swap frees).
  mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, scene.F, scene.dirichlet);
  mortar::SparseMatrix().swap(K);
  const Eigen::VectorXd no_gap = Eigen::VectorXd::Zero(s.constraints.B.rows());
  mortar::SaddlePointProblem reduced = mortar::reduce_to_free_dofs(system, s.constraints, no_gap);
  mortar::SparseMatrix().swap(system.K);

  // 7. Condensation: u_{s_i} = -(B_r u)_i / b_i node by node (D is diagonal), u = T v, and
  //    A = T^T K T, SPD, of the displacements alone (common/contact/dual_condensation.hpp).
  mortar::CondensedContact condensed = mortar::condense_contact(reduced);
  mortar::SparseMatrix().swap(reduced.K);

  // 8. One Cholesky of A and one solve; the multipliers lambda_i = (r - A v)_{s_i}, each read
  //    off its own row: no system for them.
  mortar::DualContactOptions solve;
  solve.unilateral = false;
  solve.backend = options.backend;
  const mortar::DualContactSolution x = mortar::solve_dual_contact(condensed, solve);
  s.u = system.expand(x.u);
  s.lambda = x.lambda;

  // 9. The pressure (the coefficients lambda_i at their nodes, chapter 4's curve) and the jump.
  s.pressure = mortar::contact_pressure(gamma, s.constraints, s.lambda);
  s.jump = mortar::normal_jump(bodies, gamma, s.u);
  return s;
}

void add_function_error(const mortar::BilateralLevel& level, const mortar::ManufacturedContact& exact,
                        mortar::Row& row) {
  const mortar::BilateralSolution& s = level.solution;
  const mortar::BrokenCurve lambda_h = mortar::multiplier_function(s.gamma, s.constraints, s.lambda);
  const double error = mortar::l2_error(lambda_h, [&](double x) { return exact.pressure(x); });
  row.emplace_back("err_pressure_function", error / level.pressure_errors.norm_l2);
}

}  // namespace chapter06
