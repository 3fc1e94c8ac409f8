// One bilateral level of chapter 6: chapter 4's two bodies and rows, with the dual basis.
#pragma once

#include "common/contact/bilateral_contact.hpp"
#include "common/study/bilateral_study.hpp"

namespace chapter06 {

// K, the traces and their merged grid, the dual basis, D (diagonal) and M, the rows of B,
// Dirichlet elimination, the condensation of the non-mortar normal dofs, one Cholesky of
// T^T K T, then u, the multipliers node by node, the pressure and the jump.
mortar::BilateralSolution solve_dual_mortar(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                            const mortar::BilateralOptions& options);

// The column err_pressure_function: ||p - sum_i lambda_i psi_i||_{L2} / ||p||_{L2}, the
// multiplier as the function it is (it jumps at the nodes), not its coefficients at the nodes.
void add_function_error(const mortar::BilateralLevel& level, const mortar::ManufacturedContact& exact,
                        mortar::Row& row);

}  // namespace chapter06
