// The figures of chapter 7 that chapters 3 and 4 do not draw: P2 beside P1 at equal unknowns
// and at equal time.
#pragma once

#include <string>

#include "common/study/bilateral_study.hpp"

namespace chapter07 {

// p2_vs_p1: the energy and L2 errors against the number of unknowns for both degrees, with
// the slopes h^2 = N^{-1} and h = N^{-1/2} of the energy norm (Theorem 4.2, q = 2 and q = 1).
// error_vs_time: the energy error against wall time in units of the finest P1 level's limit,
// both degrees and both limits.
// mesh: the mesh options for the titles (mesh_label).
void plot_p2_against_p1(const std::string& folder, const mortar::ConvergenceTable& p2,
                        const mortar::ConvergenceTable& p1, const std::string& matching,
                        const std::string& mesh, bool run);

}  // namespace chapter07
