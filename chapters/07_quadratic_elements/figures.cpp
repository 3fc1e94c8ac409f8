#include "figures.hpp"

#include <vector>

#include "common/study/contact_plots.hpp"
#include "common/study/plot.hpp"

namespace chapter07 {

namespace {
// column / unit for every row, as a series
mortar::Series scaled_series(const mortar::ConvergenceTable& table, const std::string& x, double unit,
                             const std::string& title, const std::string& style) {
  mortar::Series s = mortar::table_series(table, x, "err_energy", title, style);
  for (double& v : s.x) v /= unit;
  return s;
}
}  // namespace

void plot_p2_against_p1(const std::string& folder, const mortar::ConvergenceTable& p2,
                        const mortar::ConvergenceTable& p1, const std::string& matching,
                        const std::string& mesh, bool run) {
  // the key over the empty decades room_above_data adds, never over a curve
  mortar::Figure dofs = mortar::log_log_figure(matching + " matching, " + mesh + ": P2 and P1 at equal unknowns",
                                               "unknowns (both bodies) [-]", "relative error [-]", "top right");
  dofs.series = {mortar::table_series(p2, "dofs", "err_energy", "P2: u, energy norm", "pt 7 lw 2 lc rgb '#d62728'"),
                 mortar::table_series(p1, "dofs", "err_energy", "P1: u, energy norm", "pt 5 lw 2 lc rgb '#1f77b4'"),
                 mortar::table_series(p2, "dofs", "err_l2", "P2: u, L2", "pt 6 dt 2 lw 2 lc rgb '#d62728'"),
                 mortar::table_series(p1, "dofs", "err_l2", "P1: u, L2", "pt 4 dt 2 lw 2 lc rgb '#1f77b4'")};
  // anchored at the coarsest level (the smallest x), shifted away from the data
  if (matching == "integral")
    dofs.slopes = {{-1.0, 0, 0.4, "slope -1 = h^2: energy, Theorem 4.2 with q = 2", ""},
                   {-0.5, 1, 0.5, "slope -1/2 = h: energy, Theorem 4.2 with q = 1", ""}};
  else
    dofs.slopes = {{-0.25, 0, 0.4, "slope -1/4 = h^{1/2}: energy, Theorem 4.1 (either degree)", ""}};
  mortar::room_above_data(dofs, 2);
  mortar::write_figure(folder, "p2_vs_p1", dofs, run);

  const double unit = p1.column("limit_s").back();
  mortar::Figure time = mortar::log_log_figure(
      matching + " matching, " + mesh + ": energy error against wall time, P2 and P1",
      "wall time of the level / the limit of the finest P1 level [-]", "relative error, energy norm [-]", "top right");
  time.series = {scaled_series(p2, "time_s", unit, "P2: the whole solve", "pt 7 lw 2 lc rgb '#d62728'"),
                 scaled_series(p1, "time_s", unit, "P1: the whole solve", "pt 5 lw 2 lc rgb '#1f77b4'"),
                 scaled_series(p2, "limit_s", unit, "P2 physical limit (K, Cholesky, one solve)",
                               "pt 1 dt 3 lw 2 lc rgb '#d62728'"),
                 scaled_series(p1, "limit_s", unit, "P1 physical limit", "pt 1 dt 3 lw 2 lc rgb '#1f77b4'")};
  mortar::write_figure(folder, "error_vs_time", time, run);
}

}  // namespace chapter07
