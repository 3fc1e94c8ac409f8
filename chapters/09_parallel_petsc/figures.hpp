// Step 7 of chapter 9: the figures, written by rank 0 from the convergence table.
#pragma once

#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"

namespace chapter09 {

// iterations.png: the Krylov iterations of every Newton step against the dofs of its level
// (flat in h would be AMG's promise); time.png: the distributed contact solve, chapter 6's
// CHOLMOD solve and the physical limit against the dofs.
void plot_solves(const std::string& folder, const mortar::ConvergenceTable& table,
                 const std::vector<std::vector<int>>& iterations, const std::string& solver, double rtol,
                 bool run);

}  // namespace chapter09
