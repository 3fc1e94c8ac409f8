#include "common/contact_plots.hpp"

#include <algorithm>
#include <numeric>

namespace mortar {

namespace {
Series curve_series(const InterfaceCurve& c, const std::string& title, const std::string& style,
                    const std::string& extra) {
  // sort by x: element values along Gamma_c arrive in mesh order
  std::vector<std::size_t> order(c.x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.x[a] < c.x[b]; });
  Series s{title, {}, {}, style, extra};
  for (std::size_t i : order) {
    s.x.push_back(c.x[i]);
    s.y.push_back(c.value[i]);
  }
  return s;
}
}  // namespace

void plot_contact_errors(const std::string& folder, const ConvergenceTable& table,
                         const std::string& title, const std::vector<ReferenceSlope>& slopes,
                         bool run) {
  Figure fig;
  fig.title = title;
  fig.xlabel = "h = max(h1, h2) [m]";
  fig.ylabel = "relative error [-]";
  fig.log_x = fig.log_y = true;
  fig.key = "bottom right";
  const auto h = table.column("h");
  fig.series.push_back({"u, broken energy norm", h, table.column("err_energy"), "linespoints", "pt 7 lw 2"});
  fig.series.push_back({"u, L^2", h, table.column("err_l2"), "linespoints", "pt 5 lw 2"});
  fig.series.push_back({"pressure, L^2(Gamma_c)", h, table.column("err_pressure"), "linespoints", "pt 9 lw 2"});
  fig.series.push_back({"jump [u.n], L^2(Gamma_c) / ||u.n||", h, table.column("err_jump"), "linespoints", "pt 11 lw 2"});
  fig.slopes = slopes;
  write_figure(folder, "error_vs_h", fig, run);
}

void plot_contact_error_vs_time(const std::string& folder, const ConvergenceTable& table,
                                const std::string& title, bool run) {
  const TimedErrors data{table.column("err_energy"), table.column("time_s"), table.column("limit_s"),
                         "this program (assemble, constrain, solve)",
                         "physical limit (assemble K, Cholesky, one solve)"};
  write_figure(folder, "error_vs_time",
               error_against_time(title, "wall time [s]", "relative error, broken energy norm [-]", data), run);
}

void plot_pressure(const std::string& folder, const BilateralLevel& level,
                   const ManufacturedContact& exact, const std::string& title, bool run) {
  Figure fig;
  fig.title = title;
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "contact pressure p = -sigma_N [Pa]";
  fig.key = "top right";
  Series reference{"exact -sigma_N", {}, {}, "lines", "lw 2 lc rgb '#000000'"};
  const double L = level.jump.x.back();
  for (int i = 0; i <= 400; ++i) {
    reference.x.push_back(L * i / 400.0);
    reference.y.push_back(exact.pressure(L * i / 400.0));
  }
  fig.series.push_back(reference);
  fig.series.push_back(curve_series(level.pressure, "computed, at the non-mortar nodes", "linespoints",
                                    "pt 7 ps 0.8 lc rgb '#1f77b4'"));
  write_figure(folder, "pressure", fig, run);
}

void plot_jump(const std::string& folder, const BilateralLevel& level, const std::string& title,
               bool run) {
  Figure fig;
  fig.title = title;
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "[u_h.n] = u^2_y - u^1_y [m]";
  fig.key = "top right";
  fig.series.push_back(curve_series(level.jump, "jump at the merged-grid nodes (exact: 0)", "linespoints",
                                    "pt 7 ps 0.6 lc rgb '#d62728'"));
  write_figure(folder, "jump", fig, run);
}

void plot_patch_test(const std::string& folder, const PatchTestResult& pointwise,
                     const PatchTestResult& integral, bool run) {
  Figure fig;
  fig.title = "patch test, h2/h1 = 3/7: sigma_{22} in the triangles along Gamma_c (exact: -p)";
  fig.xlabel = "x of the triangle's centroid [m]";
  fig.ylabel = "sigma_{22} / p [-]";
  fig.key = "outside right top";
  fig.width = 1200;
  fig.series.push_back(curve_series(pointwise.sigma22_body1, "pointwise matching, body 1", "linespoints", "pt 6 lc rgb '#d62728'"));
  fig.series.push_back(curve_series(pointwise.sigma22_body2, "pointwise matching, body 2", "linespoints", "pt 4 lc rgb '#ff7f0e'"));
  fig.series.push_back(curve_series(integral.sigma22_body1, "integral matching, body 1", "linespoints", "pt 7 lw 2 lc rgb '#1f77b4'"));
  fig.series.push_back(curve_series(integral.sigma22_body2, "integral matching, body 2", "linespoints", "pt 5 lw 2 lc rgb '#17becf'"));
  write_figure(folder, "patch_test", fig, run);
}

}  // namespace mortar
