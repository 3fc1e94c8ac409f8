#include "figures.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "common/study/contact_plots.hpp"
#include "common/study/plot.hpp"
#include "common/study/two_body_pictures.hpp"

namespace chapter08 {

namespace {
std::string scene_title(const Options& o) {
  char text[160];
  std::snprintf(text, sizeof text, "%s, %s F = %g, h_2/h_1 = %g, non-mortar body %d", o.scene.c_str(), o.law.c_str(),
                o.friction, o.h_ratio, o.nonmortar);
  return text;
}

mortar::Series sampled(const std::function<double(double)>& f, double a, double b, const std::string& title,
                       const std::string& style, double factor = 1) {
  mortar::Series s{title, {}, {}, "lines", style};
  for (int k = 0; k <= 800; ++k) {
    const double x = a + (b - a) * k / 800;
    s.x.push_back(x);
    s.y.push_back(factor * f(x));
  }
  return s;
}
}  // namespace

void plot_meshes(const std::string& folder, const FrictionalLevel& coarsest, const Options& o, bool run) {
  // the dual multipliers live on the nodes xi^1 of the non-mortar trace, glued by integral matching
  mortar::write_figure(folder, "meshes",
                       mortar::two_body_meshes(coarsest.bodies, coarsest.gamma, mortar::Matching::integral,
                                               scene_title(o)),
                       run);
}

void plot_zones(const std::string& folder, const FrictionalLevel& r, const Options& o, const ExactCurves& exact,
                bool run) {
  const StepResult& s = r.last();
  mortar::Figure fig;
  fig.title = "the last load step on the finest mesh: " + scene_title(o);
  fig.xlabel = "x along Γ_c [m]";
  // the scenes are nondimensional (E_1 = 1 Pa, L = 1 m): a stress of 3e-4 Pa is 3e-4 E_1
  fig.ylabel = "shear λ_t and bounds ±s [Pa] = multiples of E_1";
  fig.key = "below maxrows 2";
  fig.width = 1000;
  fig.height = 720;
  const double a = exact.x_min < exact.x_max ? exact.x_min : 0.0, b = exact.x_min < exact.x_max ? exact.x_max : o.L;
  fig.settings = {"set xrange [" + std::to_string(a) + ":" + std::to_string(b) + "]", "set grid"};
  // s_h at each node: F lambda_n (Coulomb) or the given threshold read back from the exact curve
  mortar::Series bound{"threshold s_h = F λ_n,h", {}, {}, "lines", "lw 1 lc rgb '#7f7f7f'"};
  mortar::Series lower{"-s_h", {}, {}, "lines", "lw 1 dt 2 lc rgb '#7f7f7f'"};
  mortar::Series stick{"stick nodes: λ_t,i", {}, {}, "points", "pt 7 ps 1.0 lc rgb '#1f77b4'"};
  mortar::Series slip{"slip nodes", {}, {}, "points", "pt 9 ps 1.2 lc rgb '#d62728'"};
  mortar::Series open{"open nodes", {}, {}, "points", "pt 2 ps 0.9 lc rgb '#2ca02c'"};
  for (std::size_t k = 0; k < s.shear.x.size(); ++k) {
    const double x = s.shear.x[k];
    if (x < a || x > b) continue;
    const double threshold = o.law == "tresca" && exact.bound ? exact.bound(x) : o.friction * std::max(0.0, s.pressure.value[k]);
    bound.x.push_back(x);
    bound.y.push_back(threshold);
    lower.x.push_back(x);
    lower.y.push_back(-threshold);
    mortar::Series& target = s.status[k] == mortar::NodeStatus::stick ? stick
                             : s.status[k] == mortar::NodeStatus::slip ? slip
                                                                       : open;
    target.x.push_back(x);
    target.y.push_back(s.shear.value[k]);
  }
  if (o.law == "tresca") bound.title = "Tresca threshold s = F p at the nodes";
  for (mortar::Series* series : {&bound, &lower, &stick, &slip, &open})
    if (!series->x.empty()) fig.series.push_back(*series);
  if (exact.shear) fig.series.push_back(sampled(exact.shear, a, b, exact.label, "lw 2 dt 3 lc rgb '#000000'"));
  mortar::write_figure(folder, "zones", fig, run);
}

void plot_errors(const std::string& folder, const mortar::ConvergenceTable& table, const Options& o, bool run) {
  mortar::Figure fig = mortar::log_log_figure("relative errors against h: " + scene_title(o), "h = max(h_1, h_2) [m]",
                                              "relative error [-]", "bottom right");
  const bool exact = o.scene != "cattaneo";  // measured against an exact solution of the finite problem
  if (exact) {
    fig.series.push_back(mortar::table_series(table, "h", "err_energy", "u, energy norm", "pt 7 lw 2 lc rgb '#d62728'"));
    fig.series.push_back(mortar::table_series(table, "h", "err_l2", "u, L^2", "pt 5 lw 2 lc rgb '#1f77b4'"));
    fig.series.push_back(mortar::table_series(table, "h", "err_pressure", "λ_n (nodal), L^2", "pt 9 lw 2 lc rgb '#2ca02c'"));
    fig.series.push_back(mortar::table_series(table, "h", "err_tangential", "λ_t (nodal), L^2", "pt 11 lw 2 lc rgb '#9467bd'"));
    fig.slopes = {{1, 0, 0.5, "slope 1", "", true}, {2, 1, 0.5, "slope 2", "", true}};
  } else {
    fig.series.push_back(mortar::table_series(table, "h", "err_tangential_traction", "λ_t against Cattaneo-Mindlin, L^2",
                                              "pt 7 lw 2 lc rgb '#d62728'"));
    fig.series.push_back(mortar::table_series(table, "h", "err_hertz_pressure", "λ_n against Hertz, L^2",
                                              "pt 5 lw 2 lc rgb '#1f77b4'"));
    fig.slopes = {{1, 0, 0.5, "slope 1", "", true}};
  }
  mortar::write_figure(folder, "errors_vs_h", fig, run);
  mortar::TimedErrors timed;
  timed.error = table.column(exact ? "err_energy" : "err_tangential_traction");
  timed.time_s = table.column("time_s");
  timed.limit_s = table.column("limit_s");
  timed.program_label = o.scene == "manufactured" ? "semismooth Newton (whole solve)" : "semismooth Newton (whole load path)";
  timed.limit_label = "physical limit: assembly + one Cholesky of K";
  mortar::write_figure(folder, "error_vs_time",
                       mortar::error_against_time("error against wall time: " + scene_title(o), "wall time [s]",
                                                  exact ? "energy error of u [-]" : "L^2 error of λ_t [-]",
                                                  timed),
                       run);
}

void plot_newton(const std::string& folder, const Options& o, const FrictionalLevel& r, bool run) {
  mortar::Figure fig;
  fig.title = "semismooth Newton on the finest mesh, " + scene_title(o) + ": the residual after each step";
  fig.xlabel = "Newton step";
  fig.ylabel = "largest nodal residual, each node against its own size [-]";
  fig.log_y = true;
  fig.key = "top right";
  fig.settings = {"set xtics 1", "set grid"};
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const auto& res = r.steps[k].solution.residuals;
    mortar::Series s{"load step " + std::to_string(k), {}, {}, "linespoints",
                     std::string("pt 7 lw 2 lc rgb '") + colours[k % 8] + "'"};
    for (std::size_t j = 0; j < res.size(); ++j) {
      s.x.push_back(static_cast<double>(j + 1));
      s.y.push_back(std::max(res[j], 1e-17));  // an exact zero has no place on a log axis
    }
    fig.series.push_back(s);
  }
  fig.settings.push_back("set arrow from graph 0, first 1e-12 to graph 1, first 1e-12 nohead dt 2 lc rgb '#7f7f7f'");
  fig.settings.push_back("set label 'tolerance 1e-12' at graph 0.02, first 3e-12 tc rgb '#7f7f7f'");
  mortar::write_figure(folder, "newton", fig, run);
}

void plot_stick_zone(const std::string& folder, const Options& o, const std::vector<CattaneoStep>& steps, double a,
                     bool run) {
  mortar::Figure fig;
  fig.title = scene_title(o) + ": the stick zone as Q grows (finest mesh)";
  fig.xlabel = "Q / (F P) [-]";
  fig.ylabel = "stick half-width / a [-]";
  fig.key = "bottom left";
  fig.settings = {"set xrange [0:1]", "set yrange [0:1.05]", "set grid"};
  mortar::Series computed{"computed c_h / a (a from Hertz at the computed P)", {}, {}, "points", "pt 7 ps 1.3 lc rgb '#d62728'"};
  for (const CattaneoStep& c : steps)
    if (c.step > 0) {
      computed.x.push_back(c.q_ratio);
      computed.y.push_back(c.c_h / a);
    }
  fig.series.push_back(sampled([](double t) { return std::sqrt(std::max(0.0, 1 - t)); }, 0, 1,
                               "c / a = (1 - Q/(F P))^{1/2}", "lw 2 lc rgb '#000000'"));
  fig.series.push_back(computed);
  mortar::write_figure(folder, "stick_zone", fig, run);
}

}  // namespace chapter08
