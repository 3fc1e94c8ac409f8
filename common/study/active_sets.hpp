// How a Newton method's active set moves, step by step (chapters 5 and 6): which rows of B it
// held active at each step, at the node each row sits on, so a reader sees the contact zone
// grow or shrink from its first guess to the set that repeats.
#pragma once

#include <string>
#include <vector>

namespace mortar {

struct ActiveSetHistory {
  std::string label;                    // the method, e.g. "standard basis, active set on S"
  std::vector<double> x;                // the position on Gamma_c of each row's node
  std::vector<std::vector<int>> steps;  // the active rows of each step (sorted), in order
};

// One line per step: |A|, the rows that entered and left since the step before, and the
// extent of A along Gamma_c.
void print_active_sets(const ActiveSetHistory& history);

// active_sets.csv (method, step, x, active: one row per node and step) and active_sets.png:
// the active nodes of each step (x along Gamma_c against the step), one colour per method.
void write_active_sets(const std::string& folder, const std::string& title,
                       const std::vector<ActiveSetHistory>& methods, bool run_gnuplot);

}  // namespace mortar
