#include "figures.hpp"

#include <cmath>
#include <cstdio>

#include "common/study/plot.hpp"

namespace chapter02 {

using mortar::Figure;
using mortar::Series;

void plot_error_vs_h(const std::string& folder, const mortar::ConvergenceTable& table, bool run) {
  Figure fig;
  fig.title = "P1 plane strain, manufactured solution: error against mesh size";
  fig.xlabel = "h, largest edge [m]";
  fig.ylabel = "relative error [-]";
  fig.log_x = fig.log_y = true;
  const auto h = table.column("h");
  fig.series.push_back({"energy norm", h, table.column("err_energy"), "linespoints", "pt 7 lw 2"});
  fig.series.push_back({"L^2 norm", h, table.column("err_l2"), "linespoints", "pt 5 lw 2"});
  fig.slopes.push_back({1.0, 0, 0.4, "slope 1 (theory, energy)", "dt 2 lw 2 lc rgb '#555555'"});
  fig.slopes.push_back({2.0, 1, 0.4, "slope 2 (theory, L^2)", "dt 4 lw 2 lc rgb '#555555'"});
  mortar::write_figure(folder, "error_vs_h", fig, run);
}

void plot_error_vs_time(const std::string& folder, const mortar::ConvergenceTable& table, bool run) {
  const mortar::TimedErrors data{table.column("err_energy"), table.column("time_s"), table.column("limit_s"),
                                 "this program (assemble, load, eliminate, factorize, solve)",
                                 "physical limit (assemble K, Cholesky, one solve)"};
  mortar::write_figure(folder, "error_vs_time",
                       mortar::error_against_time("P1 plane strain: error against wall time", "wall time [s]",
                                                  "relative error in the energy norm [-]", data),
                       run);
}

void plot_deformed_mesh(const std::string& folder, const mortar::Mesh& mesh,
                        const Eigen::VectorXd& u, bool run) {
  // Magnify so the largest displacement is 8% of the body size.
  double umax = 0;
  for (int a = 0; a < mesh.num_nodes(); ++a) umax = std::max(umax, u.segment<2>(2 * a).norm());
  const double scale = umax > 0 ? 0.08 / umax : 1.0;
  char title[160];
  std::snprintf(title, sizeof title,
                "deformed mesh, %d triangles, displacement magnified %.3g times",
                static_cast<int>(mesh.triangles.size()), scale);
  Figure fig;
  fig.title = title;
  fig.xlabel = "x [m]";
  fig.ylabel = "y [m]";
  fig.equal_axes = true;
  fig.key = "outside top center horizontal";
  fig.width = fig.height = 800;
  fig.series.push_back(mortar::mesh_edges(mesh, "reference configuration", "lc rgb '#bbbbbb'"));
  fig.series.push_back(mortar::mesh_edges(mortar::displaced(mesh, u, scale),
                                          "deformed (Dirichlet: left, bottom; traction: right, top)",
                                          "lc rgb '#1f4e9a'"));
  mortar::write_figure(folder, "deformed_mesh", fig, run);
}

}  // namespace chapter02
