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
  fig.series.push_back({"energy norm", h, table.column("err_energy"), "linespoints", "pt 7 lw 2 lc rgb '#1f77b4'"});
  fig.series.push_back({"L^2 norm", h, table.column("err_l2"), "linespoints", "pt 5 lw 2 lc rgb '#2ca02c'"});
  // each reference slope in its own colour and dash (mortar::reference_slope_style)
  fig.slopes.push_back({1.0, 0, 0.4, "slope 1 (theory, energy)", ""});
  fig.slopes.push_back({2.0, 1, 0.4, "slope 2 (theory, L^2)", ""});
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
  // Magnify so the largest displacement is 12% of the body size: the deformed mesh then leaves
  // the reference one visibly wherever the body moves.
  double umax = 0;
  for (int a = 0; a < mesh.num_nodes(); ++a) umax = std::max(umax, u.segment<2>(2 * a).norm());
  const double scale = umax > 0 ? 0.12 / umax : 1.0;
  char title[160], deformed[160];
  std::snprintf(title, sizeof title, "deformed mesh over the reference mesh, %d triangles, displacement magnified %.3g times",
                static_cast<int>(mesh.triangles.size()), scale);
  std::snprintf(deformed, sizeof deformed,
                "deformed, displacement x %.3g (Dirichlet: left, bottom; traction: right, top)", scale);
  Figure fig;
  fig.title = title;
  fig.xlabel = "x [m]";
  fig.ylabel = "y [m]";
  fig.equal_axes = true;
  fig.key = "outside top center vertical";
  fig.width = 900;
  fig.height = 850;
  fig.settings.push_back("unset grid");  // grid lines would read as mesh edges
  fig.series.push_back(mortar::mesh_edges(mesh, "reference mesh (undeformed)", "lw 2.5 lc rgb '#f4a582'"));
  fig.series.push_back(mortar::mesh_edges(mortar::displaced(mesh, u, scale), deformed, "lw 1 lc rgb '#1f4e9a'"));
  mortar::write_figure(folder, "deformed_mesh", fig, run);
}

}  // namespace chapter02
