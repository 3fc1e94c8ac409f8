#include "figures.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "common/study/plot.hpp"
#include "distributed_system.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

void plot_solves(const std::string& folder, const mortar::ConvergenceTable& table, const std::string& solver,
                 double rtol, bool run) {
  const std::vector<double> dofs = table.column("dofs");
  const int ranks = static_cast<int>(table.column("ranks").back());
  mortar::Figure it;
  it.title = "Krylov iterations of the contact solve (" + solver + ", " + std::to_string(ranks) + " ranks)";
  it.xlabel = "unknowns";
  it.ylabel = "Krylov iterations";
  it.log_x = true;
  it.settings = {"set yrange [0:*]"};
  it.key = "bottom right";
  char label[96];
  std::snprintf(label, sizeof label, "the largest solve (the final one, to ‖Bρ‖ ≤ %g ‖Bb‖, ρ the residual)", rtol);
  it.series = {{"all solves of the level together", dofs, table.column("ksp_iterations_total"), "linespoints", ""},
               {label, dofs, table.column("ksp_iterations_max"), "linespoints", ""}};
  mortar::write_figure(folder, "iterations", it, run);

  const auto& columns = table.columns();
  if (std::find(columns.begin(), columns.end(), "cholmod_time_s") == columns.end()) return;
  mortar::Figure t;
  t.title = "Time of the whole contact solve against the unknowns";
  t.xlabel = "unknowns";
  t.ylabel = "wall time [s]";
  t.log_x = t.log_y = true;
  t.series = {{"PETSc, " + solver + ", " + std::to_string(ranks) + " ranks (slowest rank)", dofs, table.column("time_s"),
               "linespoints", ""},
              {"chapter 6: CHOLMOD, one factorization per Newton step", dofs, table.column("cholmod_time_s"),
               "linespoints", ""},
              {"physical limit: assemble, factorize and solve K once", dofs, table.column("limit_s"), "linespoints",
               ""}};
  t.slopes = {{1, 2, 0.5, "slope 1 (O(n))", ""}};
  mortar::write_figure(folder, "time", t, run);
}

void plot_partition(const std::string& folder, const RowSplit& split, const mortar::Material& body1,
                    const mortar::Material& body2, bool run) {
  const int ranks = static_cast<int>(split.ranks());
  mortar::Figure f;
  f.title = "Who integrates which triangle: " + std::to_string(ranks) + " ranks, rows split by cell rows";
  f.xlabel = "x [m]";
  f.ylabel = "y [m]";
  f.equal_axes = true;
  f.key = "outside right top";
  f.width = 760;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int r = 0; r < ranks; ++r) {
    const Ownership rows = split.ownership(r);
    char title[96];
    std::snprintf(title, sizeof title, "rank %d: rows %d-%d", r, static_cast<int>(rows.first),
                  static_cast<int>(rows.last - 1));
    mortar::Series s{title, {}, {}, "lines", "lw 1.5"};
    const Part part = split.part(r, body1, body2);  // each rank's own band, as it builds it
    for (int l = 0; l < 2; ++l) {
      const mortar::Mesh& mesh = part.bodies.body(l).mesh;
      for (const auto& t : mesh.triangles) {
        for (int k = 0; k <= 3; ++k) {
          s.x.push_back(mesh.nodes[t[k % 3]].x());
          s.y.push_back(mesh.nodes[t[k % 3]].y());
        }
        s.x.push_back(nan);
        s.y.push_back(nan);
      }
    }
    f.series.push_back(s);
  }
  mortar::write_figure(folder, "partition", f, run);
}

}  // namespace chapter09
