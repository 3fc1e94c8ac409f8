// The pressure's error away from the ends of Gamma_c (README.md, "The pressure"). On the middle
// half [L/4, 3L/4] the P1 end elements of M_h^1 no longer reach: there lambda_h and the best
// approximation in M_h^1 show the orders of their own, which the whole-line norms hide.
#pragma once

#include "common/study/bilateral_study.hpp"

namespace chapter07 {

// Three columns for each level's row, relative to ||p||_{L2(Gamma_c)} like chapter 4's:
//   err_pressure_middle        ||lambda_h - p|| in L2(L/4, 3L/4);
//   err_pressure_best_middle   ||Pi_h p - p|| there, Pi_h the L2 projection onto M_h^1;
//   err_pressure_means_middle  (sum_e |e| m_e^2)^{1/2}, m_e = int_e (lambda_h - p) / |e|: the
//                              smooth part of the error, element by element.
// The L2 norms integrate over [L/4, 3L/4] exactly, cutting the elements of the non-mortar trace
// there; the means are over the elements inside it.
void add_middle_half_errors(const mortar::BilateralLevel& level, const mortar::ManufacturedContact& exact,
                            mortar::Row& row);

}  // namespace chapter07
