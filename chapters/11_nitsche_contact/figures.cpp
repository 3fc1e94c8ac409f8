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
  for (std::size_t k = 0; k < method_names().size(); ++k) {
    const std::string& m = method_names()[k];
    fig.series.push_back({label(m, o), h, table.column(error + "_" + m), "linespoints",
                          "lw 1.5 lc rgb '" + mortar::series_colour(k) + "'", false});
  }
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
  for (std::size_t k = 0; k < finest.methods.size(); ++k) {
    const MethodResult& r = finest.methods[k];
    std::vector<double> p;
    for (double v : r.pressure_samples) p.push_back(v / p0);
    fig.series.push_back({label(r.name, o), s, p, "lines", "lw 1.5 lc rgb '" + mortar::series_colour(k) + "'", false});
  }
  fig.settings.push_back("set yrange [0:1.15]");
  return fig;
}

// One panel of the gamma0 sweep: `value` of every converged run against gamma0, per variant.
Figure sweep_panel(const std::vector<SweepPoint>& sweep, const std::string& title, const std::string& ylabel,
                   double (*value)(const MethodResult&), bool log_y) {
  Figure fig;
  fig.title = title;
  fig.xlabel = "gamma_0 (gamma = gamma_0 E / h)";
  fig.ylabel = ylabel;
  fig.log_x = true;
  fig.log_y = log_y;
  fig.key = "top right";
  fig.height = 420;
  std::size_t k = 0;
  for (double theta : {1.0, 0.0, -1.0, 2.0}) {
    Series s{theta > 1 ? "penalty" : "Nitsche, theta = " + std::to_string(static_cast<int>(theta)), {}, {},
             "linespoints", "lw 1.5 lc rgb '" + mortar::series_colour(k++) + "'", false};
    for (const SweepPoint& p : sweep)
      if (p.theta == theta && p.result.converged && std::isfinite(value(p.result))) {
        s.x.push_back(p.gamma0);
        s.y.push_back(value(p.result));
      }
    fig.series.push_back(s);
  }
  return fig;
}

Figure sweep_figure(const std::vector<SweepPoint>& sweep, int level) {
  char title[160];
  std::snprintf(title, sizeof title, "Against gamma_0, level %d: energy error (runs that did not converge left out)", level);
  Figure fig = sweep_panel(sweep, title, "relative energy error", [](const MethodResult& r) { return r.err_energy; }, true);
  Figure pressure = sweep_panel(sweep, "L2 error of the pressure", "relative L2 pressure error",
                                [](const MethodResult& r) { return r.err_pressure; }, true);
  pressure.key = "top center";
  mortar::room_above_data(pressure, 2);
  Figure steps = sweep_panel(sweep, "Newton steps (from u = 0 inside)", "Newton steps",
                             [](const MethodResult& r) { return static_cast<double>(r.newton_steps); }, false);
  steps.key = "top center";
  steps.settings.push_back("set yrange [0:*]\nset offsets 0, 0, graph 0.6, 0");
  fig.panels.push_back(pressure);
  fig.panels.push_back(steps);
  return fig;
}

Figure stiffness_figure(const std::vector<StiffnessPoint>& points, int level) {
  Figure fig;
  char title[160];
  std::snprintf(title, sizeof title, "Pressure error against E_1/E_2, level %d (runs that did not converge left out)", level);
  fig.title = title;
  fig.xlabel = "E_1 / E_2";
  fig.ylabel = "relative L2 pressure error";
  fig.log_x = fig.log_y = true;
  fig.key = "top center";
  const std::pair<const char*, const char*> kinds[] = {{"body1", "Nitsche, body 1's traction"},
                                                       {"body2", "Nitsche, body 2's traction"},
                                                       {"harmonic", "Nitsche, weighted h/E (softer body)"},
                                                       {"mortar", "mortar, standard basis (softer body non-mortar)"},
                                                       {"dual", "mortar, dual basis"}};
  std::size_t k = 0;
  for (const auto& [kind, title_of_kind] : kinds) {
    Series s{title_of_kind, {}, {}, "linespoints", "lw 1.5 lc rgb '" + mortar::series_colour(k++) + "'", false};
    for (const StiffnessPoint& p : points)
      if ((p.traction == kind || p.result.name == kind) && p.result.converged) {
        s.x.push_back(p.ratio);
        s.y.push_back(p.result.err_pressure);
      }
    fig.series.push_back(s);
  }
  mortar::room_above_data(fig, 2);
  return fig;
}

}  // namespace

void write_figures(const Options& o, const mortar::ConvergenceTable& table, const std::vector<Level>& levels,
                   const Scene& scene, const std::vector<SweepPoint>& sweep,
                   const std::vector<StiffnessPoint>& stiffness, bool run_gnuplot) {
  mortar::write_figure(o.out, "energy_rates", rates_figure(o, table, "err_energy", "energy", 1), run_gnuplot);
  mortar::write_figure(o.out, "pressure_rates", rates_figure(o, table, "err_pressure", "L2 pressure", 1), run_gnuplot);
  mortar::write_figure(o.out, "pressure_edge", pressure_figure(o, levels.back(), scene), run_gnuplot);
  if (!sweep.empty()) mortar::write_figure(o.out, "gamma_sweep", sweep_figure(sweep, o.sweep_level), run_gnuplot);
  if (!stiffness.empty())
    mortar::write_figure(o.out, "stiffness_sweep", stiffness_figure(stiffness, o.sweep_level), run_gnuplot);
}

}  // namespace chapter11
