#include "figures.hpp"

#include <cmath>
#include <cstdio>

#include "common/study/plot.hpp"

namespace chapter11 {

namespace {

using mortar::Figure;
using mortar::Series;

std::string label(const std::string& method, const Options& o) {
  char text[80];
  if (method == "nitsche") {
    std::snprintf(text, sizeof text, "Nitsche, theta = %g, gamma_0 = %g", o.theta, o.gamma0);
    return text;
  }
  if (method == "penalty") {
    std::snprintf(text, sizeof text, "penalty, gamma = %g E/h", o.penalty_gamma0);
    return text;
  }
  if (method == "penalty_fixed") return "penalty, gamma fixed";
  if (method == "mortar") return "mortar, standard basis";
  return "mortar, dual basis";
}

Figure rates_figure(const Options& o, const mortar::ConvergenceTable& table, const std::string& error,
                    const std::string& what, double slope) {
  Figure fig;
  char title[160];
  std::snprintf(title, sizeof title, "Exact Hertz, h_2/h_1 = %g: %s error of every method", o.h_ratio, what.c_str());
  fig.title = title;
  fig.xlabel = "h [m]";
  fig.ylabel = "relative " + what + " error";
  fig.log_x = fig.log_y = true;
  fig.key = "bottom right";
  const std::vector<double> h = table.column("h");
  for (const std::string& m : method_names())
    fig.series.push_back({label(m, o), h, table.column(error + "_" + m), "linespoints", "", false});
  fig.slopes.push_back({slope, 3, 0.5, "", "", false});
  return fig;
}

Figure pressure_figure(const Options& o, const Level& finest, const Scene& scene) {
  Figure fig;
  char title[160];
  std::snprintf(title, sizeof title, "Pressure at the contact edge x_0 + a, finest level (h_1 = %.3g m)", finest.h1);
  fig.title = title;
  fig.xlabel = "(x - x_0) / a";
  fig.ylabel = "p / p_0";
  fig.key = "top right";
  const double a = scene.exact->half_width(), x0 = scene.exact->centre(), p0 = scene.exact->peak_pressure();
  std::vector<double> s, exact;
  for (double x : finest.sample_x) {
    s.push_back((x - x0) / a);
    exact.push_back(scene.exact->pressure(x) / p0);
  }
  fig.series.push_back({"exact", s, exact, "lines", "lc rgb '#000000' lw 2"});
  for (const MethodResult& r : finest.methods) {
    std::vector<double> p;
    for (double v : r.pressure_samples) p.push_back(v / p0);
    fig.series.push_back({label(r.name, o), s, p, "lines", "", false});
  }
  return fig;
}

Figure sweep_figure(const std::vector<SweepPoint>& sweep, int level) {
  Figure fig;
  char title[160];
  std::snprintf(title, sizeof title, "Energy error against gamma_0, level %d (open: Newton did not converge)", level);
  fig.title = title;
  fig.xlabel = "gamma_0 (gamma = gamma_0 E / h)";
  fig.ylabel = "relative energy error";
  fig.log_x = fig.log_y = true;
  fig.key = "top right";
  for (double theta : {1.0, 0.0, -1.0, 2.0}) {
    Series converged{theta > 1 ? "penalty" : "Nitsche, theta = " + std::to_string(static_cast<int>(theta)), {}, {}, "linespoints", "", false};
    for (const SweepPoint& p : sweep)
      if (p.theta == theta && p.result.converged && std::isfinite(p.result.err_energy)) {
        converged.x.push_back(p.gamma0);
        converged.y.push_back(p.result.err_energy);
      }
    fig.series.push_back(converged);
  }
  return fig;
}

}  // namespace

void write_figures(const Options& o, const mortar::ConvergenceTable& table, const std::vector<Level>& levels,
                   const Scene& scene, const std::vector<SweepPoint>& sweep, bool run_gnuplot) {
  mortar::write_figure(o.out, "energy_rates", rates_figure(o, table, "err_energy", "energy", 1), run_gnuplot);
  mortar::write_figure(o.out, "pressure_rates", rates_figure(o, table, "err_pressure", "L2 pressure", 1), run_gnuplot);
  mortar::write_figure(o.out, "pressure_edge", pressure_figure(o, levels.back(), scene), run_gnuplot);
  if (!sweep.empty()) mortar::write_figure(o.out, "gamma_sweep", sweep_figure(sweep, o.sweep_level), run_gnuplot);
}

}  // namespace chapter11
