// P2 beside P1 at equal cost: which degree reaches a given error first, in unknowns and in time.
//
// Chapter 4's P1 study runs on meshes with twice the elements along each side (n0 doubled), so
// that at every level the P1 vertices are exactly the P2 nodes: the same number of unknowns.
// Times are compared in one unit measured in the same run, the physical limit of the finest P1
// level (assemble K, one Cholesky, one solve), never in seconds.
#pragma once

#include <string>

#include "common/study/bilateral_study.hpp"
#include "common/study/json_writer.hpp"

namespace chapter07 {

// The P1 study on the same scene: options with degree 1 and twice n0, solved by the library's
// solve_bilateral (chapter 3's and 4's matching, the same matching as the P2 run).
mortar::BilateralStudy run_p1_study(const mortar::BilateralStudyOptions& p2_options,
                                    const mortar::ManufacturedContact& exact, mortar::Matching matching);

// The unknowns and the time P2 needs to reach the energy error of P1's finest level, read off
// P2's levels by log-log interpolation between the two levels around it (NaN when P2 never
// gets there in the levels run); times in units of the finest P1 level's limit.
struct EqualError {
  double error = 0;                  // the finest P1 level's relative energy error
  double p1_dofs = 0, p2_dofs = 0;   // unknowns to reach it
  double p1_time = 0, p2_time = 0;   // wall time to reach it / the finest P1 limit
  double p1_limit_ratio = 0;         // the finest P1 level's time / its own limit
};
EqualError equal_error(const mortar::ConvergenceTable& p2, const mortar::ConvergenceTable& p1);

// results keys: p1_err_energy, p1_dofs, p2_dofs_same_error, dofs_ratio_p1_over_p2,
// time_ratio_p1_over_p2 (both times to the same error, in the same unit).
mortar::JsonObject equal_error_results(const EqualError& e);

}  // namespace chapter07
