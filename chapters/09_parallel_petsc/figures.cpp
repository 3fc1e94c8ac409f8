#include "figures.hpp"

#include <algorithm>
#include <cstdio>

#include "common/study/plot.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

void plot_solves(const std::string& folder, const mortar::ConvergenceTable& table,
                 const std::vector<std::vector<int>>& iterations, const std::string& solver, double rtol,
                 bool run) {
  const std::vector<double> dofs = table.column("dofs");
  const int ranks = static_cast<int>(table.column("ranks").back());
  mortar::Figure it;
  it.title = "Krylov iterations of each Newton step (" + solver + ", " + std::to_string(ranks) + " ranks)";
  it.xlabel = "unknowns";
  char label[64];
  std::snprintf(label, sizeof label, "iterations to ‖r‖ ≤ %g ‖b‖", rtol);
  it.ylabel = label;
  it.log_x = true;
  it.settings = {"set yrange [0:*]"};
  std::size_t steps = 0;
  for (const auto& level : iterations) steps = std::max(steps, level.size());
  for (std::size_t k = 0; k < steps; ++k) {
    mortar::Series s{"Newton step " + std::to_string(k + 1), {}, {}};
    for (std::size_t l = 0; l < iterations.size(); ++l)
      if (k < iterations[l].size()) {
        s.x.push_back(dofs[l]);
        s.y.push_back(iterations[l][k]);
      }
    it.series.push_back(s);
  }
  mortar::write_figure(folder, "iterations", it, run);

  const auto& columns = table.columns();
  if (std::find(columns.begin(), columns.end(), "limit_s") == columns.end()) return;
  mortar::Figure t;
  t.title = "Time of the whole contact solve against the unknowns";
  t.xlabel = "unknowns";
  t.ylabel = "wall time [s]";
  t.log_x = t.log_y = true;
  t.series = {{"PETSc, " + solver + ", " + std::to_string(ranks) + " ranks (slowest rank)", dofs, table.column("time_s")},
              {"chapter 6: CHOLMOD, one factorization per Newton step", dofs, table.column("cholmod_time_s")},
              {"physical limit: assemble, factorize and solve K once", dofs, table.column("limit_s")}};
  t.slopes = {{1, 2, 0.5, "slope 1 (O(n))"}};
  mortar::write_figure(folder, "time", t, run);
}

}  // namespace chapter09
