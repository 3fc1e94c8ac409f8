#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/interface/merged_grid.hpp"
#include "common/study/plot.hpp"
#include "common/interface/trace_transfer.hpp"

namespace chapter01 {

using mortar::Figure;
using mortar::Series;

namespace {
// A row of grid nodes drawn as tick marks at height y.
Series grid_row(const std::vector<double>& x, double y, const std::string& title,
                const std::string& extra) {
  Series s{title, x, std::vector<double>(x.size(), y), "points", extra};
  return s;
}

constexpr double floor_value = 1e-17;  // exact zeros cannot sit on a log axis
}  // namespace

void plot_transfers(const std::string& folder, const TransferResult& r, const TraceFunction& w,
                    bool run) {
  Figure fig;
  // the integrals go to the key, beside the curve they belong to: the title stays one short line
  char title[160], label[96];
  std::snprintf(title, sizeof title, "%s trace from side 2 (%d elements) to side 1 (%d elements)",
                w.name.c_str(), r.trace2.num_elements(), r.trace1.num_elements());
  fig.title = title;
  auto with_integral = [&](const char* what, double value) {
    std::snprintf(label, sizeof label, "%s, int = %.5f", what, value);
    return std::string(label);
  };
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "trace value w [m]";
  fig.key = "top left";  // over the room left above the curves (the y range, below)
  fig.width = 1000;
  fig.height = 650;
  Series exact{"exact w", {}, {}, "lines", "lw 1 lc rgb '#000000'"};
  for (int i = 0; i <= 400; ++i) {
    const double x = w.L * i / 400.0;
    exact.x.push_back(x);
    exact.y.push_back(w.value(x));
  }
  fig.series.push_back(exact);
  fig.series.push_back({with_integral("w2: interpolant on side 2", mortar::integral(r.trace2, r.w2)), r.trace2.x, r.w2, "linespoints",
                        "pt 6 lw 1 lc rgb '#888888'"});
  fig.series.push_back({with_integral("pointwise transfer to side 1", mortar::integral(r.trace1, r.pointwise)), r.trace1.x, r.pointwise, "linespoints",
                        "pt 9 ps 1.5 lw 2 lc rgb '#d62728'"});
  fig.series.push_back({with_integral("mortar projection to side 1", mortar::integral(r.trace1, r.mortar)), r.trace1.x, r.mortar, "linespoints",
                        "pt 7 ps 1.2 lw 2 lc rgb '#1f77b4'"});
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : fig.series) {
    lo = std::min(lo, *std::min_element(s.y.begin(), s.y.end()));
    hi = std::max(hi, *std::max_element(s.y.begin(), s.y.end()));
  }
  // the three node rows below the curves, the key's seven lines above them
  char range[96];
  std::snprintf(range, sizeof range, "set yrange [%.6g:%.6g]", lo - 0.45, hi + std::max(0.9 * (hi - lo), 0.5));
  fig.settings.push_back(range);
  const mortar::MergedGrid grid = mortar::merge_traces(r.trace1, r.trace2);
  fig.series.push_back(grid_row(r.trace1.x, lo - 0.15, "nodes xi^1 (side 1, non-mortar)", "pt 2 ps 1.5 lc rgb '#1f77b4'"));
  fig.series.push_back(grid_row(r.trace2.x, lo - 0.25, "nodes xi^2 (side 2, mortar)", "pt 2 ps 1.5 lc rgb '#888888'"));
  fig.series.push_back(grid_row(grid.breakpoints, lo - 0.35, "merged grid", "pt 1 ps 1.5 lc rgb '#2ca02c'"));
  mortar::write_figure(folder, "transfers", fig, run);
}

void plot_error_vs_h(const std::string& folder, const mortar::ConvergenceTable& table,
                     const std::string& case_label, double l2_rate, double h1_rate, bool run) {
  Figure fig;
  fig.title = "trace transfer errors against h1, " + case_label;
  fig.xlabel = "h1, side-1 element length [m]";
  fig.ylabel = "relative error on side 1 [-]";
  fig.log_x = fig.log_y = true;
  fig.key = "bottom right";
  const auto h = table.column("h1");
  const bool has_h1 = !std::isnan(h1_rate);  // NaN: w' is not square integrable (edge trace)
  if (has_h1) {
    fig.series.push_back({"mortar, H^1 seminorm", h, table.column("err_mortar_h1"), "linespoints", "pt 7 lw 2 lc rgb '#1f77b4'"});
    fig.series.push_back({"pointwise, H^1 seminorm", h, table.column("err_pointwise_h1"), "linespoints", "pt 6 lw 2 dt 2 lc rgb '#d62728'"});
  }
  fig.series.push_back({"mortar, L^2", h, table.column("err_mortar_l2"), "linespoints", "pt 5 lw 2 lc rgb '#17becf'"});
  fig.series.push_back({"pointwise, L^2", h, table.column("err_pointwise_l2"), "linespoints", "pt 4 lw 2 dt 2 lc rgb '#ff7f0e'"});
  // each reference slope in its own colour and dash (mortar::reference_slope_style)
  char label[64];
  if (has_h1) {
    std::snprintf(label, sizeof label, "reference slope %g (H^1 seminorm)", h1_rate);
    fig.slopes.push_back({h1_rate, 0, 0.5, label, ""});
  }
  std::snprintf(label, sizeof label, "reference slope %g (L^2)", l2_rate);
  fig.slopes.push_back({l2_rate, has_h1 ? 2 : 0, 0.5, label, ""});
  mortar::write_figure(folder, "error_vs_h", fig, run);
}

void plot_error_vs_time(const std::string& folder, const mortar::ConvergenceTable& table,
                        const std::string& case_label, bool run) {
  const mortar::TimedErrors data{table.column("err_mortar_l2"), table.column("time_s"), table.column("limit_s"),
                                 "mortar projection (merge, D and M, solve)",
                                 "limit: mass matrix of side 1, Cholesky, solve"};
  mortar::write_figure(folder, "error_vs_time",
                       mortar::error_against_time("mortar projection: L^2 error against wall time, " + case_label,
                                                  "wall time, best of 5 [s]", "relative L^2 error on side 1 [-]", data),
                       run);
}


void plot_integral_errors(const std::string& folder, const std::vector<IntegralCurve>& curves,
                          bool run) {
  Figure fig;
  fig.title = "conservation of int w across Gamma_c (values below 1e-17 drawn at 1e-17)";
  fig.xlabel = "h1, side-1 element length [m]";
  fig.ylabel = "|int w1 - int w2| / |int w2| [-]";
  fig.log_x = fig.log_y = true;
  // the key below the axes, never over a curve (every part of the axes holds one)
  fig.key = "at screen 0.5, screen 0.01 center bottom Left reverse";
  fig.settings.push_back("set bmargin 13");  // seven rows of key below the axis label
  fig.settings.push_back("set yrange [1e-18:*]");  // the 1e-17 floor above the frame
  fig.width = 1100;
  fig.height = 950;
  auto clamp = [](std::vector<double> v) {
    for (double& x : v) x = std::max(x, floor_value);
    return v;
  };
  int k = 0;
  for (const auto& c : curves) {
    ++k;
    fig.series.push_back({"pointwise, " + c.label, c.h1, clamp(c.pointwise), "linespoints",
                          "pt " + std::to_string(k) + " lw 1.5 dt 2 lc rgb '" + mortar::series_colour(k) + "'"});
  }
  // The mortar curves all sit at round-off: draw their worst case over every ratio.
  Series worst{"mortar, worst over all ratios", curves.front().h1, {}, "linespoints",
               "pt 7 ps 1.5 lw 3 lc rgb '#1f77b4'"};
  for (std::size_t i = 0; i < worst.x.size(); ++i) {
    double m = 0;
    for (const auto& c : curves) m = std::max(m, c.mortar[i]);
    worst.y.push_back(m);
  }
  worst.y = clamp(worst.y);
  fig.series.push_back(worst);
  mortar::write_figure(folder, "integral_error", fig, run);
}

}  // namespace chapter01
