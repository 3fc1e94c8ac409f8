// Step 7 of chapter 9: the figures, written by rank 0 from the convergence table.
#pragma once

#include <string>

#include "common/study/convergence_study.hpp"
#include "rank_part.hpp"

namespace chapter09 {

// iterations.png: the Krylov iterations of each level's contact solve, all solves together and
// the largest one, against the dofs (flat in h would be AMG's promise); time.png: the
// distributed contact solve, chapter 6's CHOLMOD solve and the physical limit against the dofs.
void plot_solves(const std::string& folder, const mortar::ConvergenceTable& table, const std::string& solver,
                 double rtol, bool run);

// partition.png: the triangles of both bodies, coloured by the rank that integrates them: each
// rank's band of cell rows (rank_part.hpp).
void plot_partition(const std::string& folder, const RowSplit& split, const mortar::Material& body1,
                    const mortar::Material& body2, bool run);

}  // namespace chapter09
