#include "figures.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>
#include <limits>

#include "common/contact/hertz_half_planes.hpp"
#include "common/interface/dual_basis.hpp"
#include "common/study/contact_plots.hpp"
#include "common/study/plot.hpp"

namespace chapter06 {

namespace {
const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b"};

// A broken curve as one series, element by element with a NaN after each so the line breaks
// at the nodes and the jumps show; only the elements `keep` accepts.
mortar::Series broken_series(const mortar::BrokenCurve& f, const std::string& title, const std::string& style,
                             const std::function<bool(std::size_t)>& keep) {
  mortar::Series s{title, {}, {}, "lines", style};
  for (std::size_t e = 0; e + 1 < f.x.size(); ++e)
    if (keep(e)) {
      s.x.insert(s.x.end(), {f.x[e], f.x[e + 1], std::numeric_limits<double>::quiet_NaN()});
      s.y.insert(s.y.end(), {f.left[e], f.right[e], 0.0});
    }
  return s;
}

// psi_i of a space on a trace, drawn element by element with a break at each node so the
// jumps of a discontinuous basis show as jumps (NaN breaks the line).
mortar::Series basis_function(const mortar::MultiplierSpace& space, const mortar::InterfaceTrace& t, int i) {
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(space.dim());
  unit[i] = 1;
  const mortar::BrokenCurve f = mortar::multiplier_function(space, t, unit);
  // drawn on its support only
  mortar::Series s = broken_series(f, "psi_" + std::to_string(i + 1), std::string("lw 2 lc rgb '") + colours[i % 7] + "'",
                                   [&](std::size_t e) { return f.left[e] != 0 || f.right[e] != 0; });
  return s;
}

mortar::Figure basis_panel(const mortar::MultiplierSpace& space, const mortar::InterfaceTrace& t,
                           const std::string& title) {
  mortar::Figure fig;
  fig.title = title;
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "psi_i(x) [-]";
  fig.key = "outside right top";
  fig.settings = {"set yrange [-1.2:2.2]", "set grid xtics", "set xtics (" + [&] {
                    std::string ticks;
                    for (int j = 0; j < t.num_nodes(); ++j)
                      ticks += (j ? ", " : "") + std::string("'x_") + std::to_string(j) + "' " + std::to_string(t.x[j]);
                    return ticks;
                  }() + ")"};
  for (int i = 0; i < space.dim(); ++i) fig.series.push_back(basis_function(space, t, i));
  return fig;
}

}  // namespace

void plot_dual_basis(const std::string& folder, bool run) {
  const mortar::InterfaceTrace t = mortar::uniform_trace(1.0, 6, 0.3, 3);
  mortar::Figure fig = basis_panel(mortar::end_modified_p1(t), t,
                                   "the hats of M_h^1 (constant on the end elements): D is tridiagonal");
  fig.height = 420;
  mortar::Figure dual = basis_panel(mortar::dual_end_modified_p1(t), t,
                                    "the dual basis on the same nodes: ∫ psi_i phi_j dx = 0 for i ≠ j, D is diagonal");
  dual.height = 420;
  fig.panels.push_back(dual);
  mortar::write_figure(folder, "dual_basis", fig, run);
}

void plot_bases_against_h(const std::string& folder, const mortar::ConvergenceTable& dual,
                          const mortar::ConvergenceTable* standard, const std::string& mesh, bool run) {
  mortar::Figure fig = mortar::log_log_figure("standard and dual multipliers, " + mesh + ": errors against h",
                               "h = max(h1, h2) [m]", "relative error [-]", "top left");
  fig.series.push_back(mortar::table_series(dual, "h", "err_energy", "dual: u, energy", "pt 7 lw 2 lc rgb '#d62728'"));
  fig.series.push_back(mortar::table_series(dual, "h", "err_pressure_function", "dual: lambda_h as a function, L2",
                                     "pt 5 lw 2 lc rgb '#ff7f0e'"));
  fig.series.push_back(mortar::table_series(dual, "h", "err_pressure", "dual: coefficients at the nodes, L2",
                                     "pt 9 lw 2 lc rgb '#9467bd'"));
  if (standard != nullptr) {
    fig.series.push_back(mortar::table_series(*standard, "h", "err_energy", "standard: u, energy", "pt 6 dt 2 lw 2 lc rgb '#1f77b4'"));
    fig.series.push_back(mortar::table_series(*standard, "h", "err_pressure", "standard: lambda_h, L2",
                                       "pt 8 dt 2 lw 2 lc rgb '#2ca02c'"));
  }
  // A slope where theory speaks: the energy (Theorem 4.2), and the dual function, whose span
  // reproduces constants only (best approximation O(h) in L2), run parallel to it.
  fig.slopes = {{1.0, 0, 0.4, "slope 1: energy (Theorem 4.2); the dual span's L2 order", ""}};
  mortar::room_above_data(fig, 2);  // the key over empty decades, clear of the coarsest points
  mortar::write_figure(folder, "standard_vs_dual", fig, run);
}

void plot_bases_against_time(const std::string& folder, const mortar::ConvergenceTable& dual,
                             const mortar::ConvergenceTable* standard, const std::string& mesh, bool run) {
  mortar::Figure fig = mortar::log_log_figure("standard and dual multipliers, " + mesh + ": energy error against wall time",
                               "wall time of the level [s]", "relative error, broken energy norm [-]", "top right");
  fig.series.push_back(mortar::table_series(dual, "time_s", "err_energy", "dual: condensed, one Cholesky of T^T K T",
                                     "pt 7 lw 2 lc rgb '#d62728'"));
  if (standard != nullptr)
    fig.series.push_back(mortar::table_series(*standard, "time_s", "err_energy", "standard: saddle point through S",
                                       "pt 6 dt 2 lw 2 lc rgb '#1f77b4'"));
  fig.series.push_back(mortar::table_series(dual, "limit_s", "err_energy", "physical limit (assemble K, Cholesky, one solve)",
                                     "pt 1 dt 3 lw 2 lc rgb '#000000'"));
  mortar::write_figure(folder, "error_vs_time", fig, run);
}

void plot_dual_pressure(const std::string& folder, const mortar::BilateralLevel& level,
                        const mortar::ManufacturedContact& exact, const std::string& mesh, bool run) {
  const mortar::BilateralSolution& s = level.solution;
  const mortar::BrokenCurve f = mortar::multiplier_function(s.gamma, s.constraints, s.lambda);
  const auto panel = [&](double a, double b, const std::string& title) {
    mortar::Figure fig;
    fig.title = title;
    fig.xlabel = "x along Gamma_c [m]";
    fig.ylabel = "contact pressure [Pa]";
    fig.key = "outside right top";
    fig.height = 420;
    mortar::Series p{"exact -sigma_N", {}, {}, "lines", "lw 2 lc rgb '#000000'"};
    const mortar::Series function = broken_series(f, "sum lambda_i psi_i (dual)", "lw 1.5 lc rgb '#ff7f0e'",
                                                  [&](std::size_t e) { return f.x[e + 1] >= a && f.x[e] <= b; });
    mortar::Series nodes{"lambda_i at their nodes", {}, {}, "points", "pt 7 ps 0.9 lc rgb '#9467bd'"};
    for (int k = 0; k <= 400; ++k) {
      const double x = a + (b - a) * k / 400.0;
      p.x.push_back(x);
      p.y.push_back(exact.pressure(x));
    }
    for (std::size_t j = 0; j < level.pressure.x.size(); ++j)
      if (level.pressure.x[j] >= a && level.pressure.x[j] <= b) {
        nodes.x.push_back(level.pressure.x[j]);
        nodes.y.push_back(level.pressure.value[j]);
      }
    fig.series = {p, function, nodes};
    fig.settings = {"set xrange [" + std::to_string(a) + ":" + std::to_string(b) + "]"};
    return fig;
  };
  const double L = level.pressure.x.back();
  const double h = s.gamma.nonmortar_trace.max_element_length();
  mortar::Figure fig = panel(0, L, "dual multipliers, " + mesh + ", coarsest level: the pressure on Gamma_c");
  fig.panels.push_back(panel(0.5 * L - 3 * h, 0.5 * L + 3 * h, "zoom on six elements: the function jumps at every node"));
  mortar::write_figure(folder, "dual_pressure", fig, run);
}

void plot_hertz_pressure(const std::string& folder, const HertzStudy& study, const HertzOptions& o, bool run) {
  const HertzLevel &s = study.standard.back(), &d = study.dual.back();
  // The contact zone and two elements beyond it on each side.
  const double L = s.pressure.x.back(), centre = 0.5 * L;
  const double a = 1.3 * std::max(s.half_width, d.half_width);
  // A yardstick, not the truth: Hertz's half-planes carrying the standard basis's total force
  // P, half-width sqrt(4 P R / (pi E*)) (hertz_half_planes.hpp). The finite blocks differ from
  // it by about 2% in L2 (chapter 5's notes, "Model error and discretization error").
  const mortar::Material m1(o.bodies.E1, o.bodies.nu1), m2(o.bodies.E2, o.bodies.nu2);
  const double e_star = 1 / ((1 - o.bodies.nu1 * o.bodies.nu1) / o.bodies.E1 + (1 - o.bodies.nu2 * o.bodies.nu2) / o.bodies.E2);
  const mortar::HertzHalfPlanes hertz(m1, m2, centre, std::sqrt(4 * s.total_force * o.R / (M_PI * e_star)), o.R);
  mortar::Series model{"half-plane Hertz at the same total force (a model)", {}, {}, "lines", "lw 1.5 dt 2 lc rgb '#444444'"};
  for (int k = 0; k <= 400; ++k) {
    const double x = centre - a + 2 * a * k / 400.0;
    model.x.push_back(x);
    model.y.push_back(hertz.pressure(x));
  }
  mortar::Figure fig;
  char title[160];
  std::snprintf(title, sizeof title, "Hertz scene, finest level (%d dofs, h_2/h_1 = %.4g): contact pressure of both bases",
                s.dofs, o.bodies.h_ratio);
  fig.title = title;
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "contact pressure [Pa]";
  mortar::Series standard{"standard: lambda_h (P1, >= 0)", {}, {}, "linespoints", "pt 6 ps 0.7 lw 2 lc rgb '#1f77b4'"};
  mortar::Series coefficients{"dual: lambda_i at their nodes", {}, {}, "points", "pt 7 ps 0.7 lc rgb '#9467bd'"};
  const mortar::Series function = broken_series(d.function, "dual: sum lambda_i psi_i", "lw 1 lc rgb '#ff7f0e'",
                                                [&](std::size_t e) { return std::fabs(d.function.x[e] - centre) <= a; });
  for (std::size_t j = 0; j < s.pressure.x.size(); ++j)
    if (std::fabs(s.pressure.x[j] - centre) <= a) {
      standard.x.push_back(s.pressure.x[j]);
      standard.y.push_back(s.pressure.value[j]);
    }
  for (std::size_t j = 0; j < d.pressure.x.size(); ++j)
    if (std::fabs(d.pressure.x[j] - centre) <= a) {
      coefficients.x.push_back(d.pressure.x[j]);
      coefficients.y.push_back(d.pressure.value[j]);
    }
  fig.series = {model, function, standard, coefficients};
  fig.key = "below";  // inside, it would hide the dual function's dips at the edges
  fig.height = 760;
  fig.settings = {"set xzeroaxis lt -1"};
  mortar::write_figure(folder, "hertz_pressure", fig, run);
}

}  // namespace chapter06
