#include "common/study/contact_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

namespace mortar {

Figure log_log_figure(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                      const std::string& key) {
  Figure fig;
  fig.title = title;
  fig.xlabel = xlabel;
  fig.ylabel = ylabel;
  fig.log_x = fig.log_y = true;
  fig.key = key;
  return fig;
}

Series table_series(const ConvergenceTable& table, const std::string& x, const std::string& y,
                    const std::string& title, const std::string& style) {
  return {title, table.column(x), table.column(y), "linespoints", style};
}

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

// One colour per quantity; a best approximation takes the colour of the quantity it stands
// beside.
struct ErrorCurve {
  std::string column, title, marker, colour;
  bool best = false;  // a best approximation in M_h^1: open markers, dotted
};
const std::vector<ErrorCurve>& error_curves() {
  static const std::vector<ErrorCurve> curves = {
      {"err_energy", "u, broken energy norm", "pt 7", "#1f77b4"},
      {"err_l2", "u, L^2", "pt 5", "#2ca02c"},
      {"err_pressure", "pressure, L^2(Gamma_c)", "pt 9", "#d62728"},
      {"err_pressure_best", "its L^2 best approximation in M_h^1", "pt 8", "#d62728", true},
      {"err_pressure_hminus", "pressure, H^{-1/2}_h = (sum_e h_e ||.||_e^2)^{1/2}", "pt 13", "#9467bd"},
      {"err_pressure_best_hminus", "the same of the L^2 best approximation", "pt 12", "#9467bd", true},
      {"err_jump", "jump [u.n], L^2(Gamma_c) / ||u.n||", "pt 11", "#ff7f0e"},
  };
  return curves;
}

// C h^p through the anchor's finest point (or, with at_coarsest, its coarsest) lowered by the
// offset, over the anchor's h range,
// with its label (the theorem that bounds the anchor): each slope in its own colour and dash
// (reference_slope_style, by its place in the list), unlike the data and the other slopes.
Series reference_line(const Series& anchor, const ReferenceSlope& r, std::size_t k) {
  std::size_t finest = 0, coarsest = 0;
  for (std::size_t i = 0; i < anchor.x.size(); ++i) {
    if (anchor.x[i] < anchor.x[finest]) finest = i;
    if (anchor.x[i] > anchor.x[coarsest]) coarsest = i;
  }
  const std::size_t through = r.at_coarsest ? coarsest : finest;
  const double C = (1 - r.offset) * anchor.y[through] / std::pow(anchor.x[through], r.slope);
  char fallback[32];
  std::snprintf(fallback, sizeof fallback, "slope %g", r.slope);
  Series line{r.label.empty() ? fallback : r.label, {}, {}, "lines",
              r.style.empty() ? reference_slope_style(k) : r.style};
  for (std::size_t i : {finest, coarsest}) {
    line.x.push_back(anchor.x[i]);
    line.y.push_back(C * std::pow(anchor.x[i], r.slope));
  }
  return line;
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
  fig.key = "bottom right font ',10'";  // below the data: the slopes keep the lower right free
  fig.width = 1000;
  fig.height = 900;
  const auto h = table.column("h");
  for (const ErrorCurve& c : error_curves())
    fig.series.push_back({c.title, h, table.column(c.column), "linespoints",
                          c.marker + " ps 1.2 lc rgb '" + c.colour + "'" + (c.best ? " lw 1 dt 3" : " lw 2")});
  for (std::size_t k = 0; k < slopes.size(); ++k) {
    const ReferenceSlope& r = slopes[k];
    if (r.anchor < 0 || r.anchor >= static_cast<int>(error_curves().size()))
      throw std::invalid_argument("plot_contact_errors: reference slope anchored to series " +
                                  std::to_string(r.anchor) + " of " + std::to_string(error_curves().size()));
    fig.series.push_back(reference_line(fig.series[r.anchor], r, k));
  }
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
  // the exact curve drawn last, over the computed points, so that both show; a margin above
  // keeps the highest points off the frame
  fig.series.push_back(curve_series(level.pressure, "computed, at the non-mortar nodes", "linespoints",
                                    "pt 7 ps 0.6 lc rgb '#1f77b4'"));
  fig.series.push_back(reference);
  fig.settings.push_back("set offsets 0, 0, graph 0.05, 0");
  write_figure(folder, "pressure", fig, run);
}

void plot_jump(const std::string& folder, const BilateralLevel& level, const std::string& title,
               bool run) {
  // Top: the whole of Gamma_c, one point per merged-grid node (a line through them would fill
  // the panel: the jump changes sign or drops to zero from one node to the next). Bottom: a
  // window of four non-mortar elements, where lines and points show the jump between nodes.
  const Series all = curve_series(level.jump, "", "points", "");
  std::vector<double> nonmortar = level.pressure.x;  // the pressure sits at the non-mortar nodes
  std::sort(nonmortar.begin(), nonmortar.end());
  const double L = all.x.empty() ? 1.0 : all.x.back();
  std::size_t first = 0;
  while (first + 1 < nonmortar.size() && nonmortar[first + 1] <= 0.3 * L) ++first;
  // four elements: 4 q node steps (a P2 trace also has its midpoints among the nodes)
  const std::size_t steps = 4 * static_cast<std::size_t>(level.pressure.degree);
  const std::size_t last = std::min(first + steps, nonmortar.empty() ? 0 : nonmortar.size() - 1);
  const double lo = nonmortar.empty() ? 0.3 * L : nonmortar[first];
  const double hi = nonmortar.empty() ? 0.35 * L : nonmortar[last];

  Figure fig;
  fig.title = title + " (exact: 0)";
  fig.xlabel = "x along Gamma_c [m]";
  fig.ylabel = "[u_h.n] = u^2_y - u^1_y [m]";
  fig.key = "top right";
  fig.width = 1000;
  fig.height = 520;
  fig.settings.push_back("set xzeroaxis lt -1");
  char window[200];
  std::snprintf(window, sizeof window,
                "set object 1 rect from %.12g, graph 0 to %.12g, graph 1 fc rgb '#ffe08a' fs solid 0.5 noborder behind",
                lo, hi);
  fig.settings.push_back(window);
  Series points = all;
  const bool quadratic = level.jump.degree == 2;
  points.title = quadratic ? "whole Gamma_c: [u_h.n] at every merged-grid node and segment midpoint"
                           : "whole Gamma_c: [u_h.n] at every merged-grid node";
  points.extra = "pt 7 ps 0.5 lc rgb '#d62728'";
  fig.series.push_back(points);

  Figure zoom;
  char zoom_title[160];
  std::snprintf(zoom_title, sizeof zoom_title,
                "zoom on the shaded window: x in [%.4g, %.4g] m, 4 non-mortar elements", lo, hi);
  zoom.title = zoom_title;
  zoom.xlabel = fig.xlabel;
  zoom.ylabel = fig.ylabel;
  zoom.key = "outside below center horizontal maxrows 1";
  zoom.width = 1000;
  zoom.height = 480;
  zoom.settings.push_back("set xzeroaxis lt -1");
  zoom.settings.push_back("set offsets 0, 0, graph 0.1, graph 0.1");
  char xrange[96];
  std::snprintf(xrange, sizeof xrange, "set xrange [%.12g:%.12g]", lo, hi);
  zoom.settings.push_back(xrange);
  const auto in_window = [&](double x) { return x >= lo - 1e-12 * L && x <= hi + 1e-12 * L; };
  Series inside{quadratic ? "[u_h.n] at the merged-grid nodes and segment midpoints" : "[u_h.n], P1 on the merged grid",
                {}, {}, quadratic ? "points" : "linespoints", "pt 7 ps 1 lw 2 lc rgb '#d62728'"};
  for (std::size_t i = 0; i < all.x.size(); ++i)
    if (in_window(all.x[i])) {
      inside.x.push_back(all.x[i]);
      inside.y.push_back(all.y[i]);
    }
  // a quadratic piece drawn as the curve it is, sampled at 16 points
  Series pieces{"[u_h.n], quadratic on each merged segment", {}, {}, "lines", "lw 2 lc rgb '#d62728'"};
  for (int e = 0; quadratic && e < level.jump.pieces(); ++e)
    // every piece that overlaps the window (the x range clips it), so none is missing at its ends
    if (level.jump.x[2 * e + 2] > lo && level.jump.x[2 * e] < hi)
      for (int k = 0; k <= 16; ++k) {
        const double s = k / 16.0;
        pieces.x.push_back(level.jump.x[2 * e] + s * (level.jump.x[2 * e + 2] - level.jump.x[2 * e]));
        pieces.y.push_back(level.jump.at(e, s));
      }
  Series nodes{"non-mortar nodes (side 1)", {}, {}, "points", "pt 2 ps 2 lw 2 lc rgb '#1f77b4'"};
  for (double x : nonmortar)
    if (x >= lo - 1e-12 * L && x <= hi + 1e-12 * L) {
      nodes.x.push_back(x);
      nodes.y.push_back(0);
    }
  zoom.series = {inside, nodes};
  if (quadratic) zoom.series.insert(zoom.series.begin(), pieces);
  fig.panels.push_back(zoom);
  write_figure(folder, "jump", fig, run);
}

void plot_patch_test(const std::string& folder, const PatchTestResult& pointwise,
                     const PatchTestResult& integral, bool run, const std::string& integral_label) {
  Figure fig;
  fig.title = "patch test, h_2/h_1 = 3/7: sigma_{22} in the triangles along Gamma_c (exact: -p)";
  fig.xlabel = "x of the triangle's centroid [m]";
  fig.ylabel = "sigma_{22} / p [-]";
  // the key below in two columns (beside the plot it took 30% of the width); the margin keeps
  // it clear of the axis label
  fig.key = "outside below maxrows 2";
  fig.settings.push_back("set bmargin 7");
  fig.width = 1000;
  fig.height = 700;
  fig.series.push_back(curve_series(pointwise.sigma22_body1, "pointwise matching, body 1", "linespoints", "pt 6 lc rgb '#d62728'"));
  fig.series.push_back(curve_series(pointwise.sigma22_body2, "pointwise matching, body 2", "linespoints", "pt 4 lc rgb '#ff7f0e'"));
  fig.series.push_back(curve_series(integral.sigma22_body1, integral_label + ", body 1", "linespoints", "pt 6 ps 2 lw 2 lc rgb '#1f77b4'"));  // open rings: both bodies sit at -1
  fig.series.push_back(curve_series(integral.sigma22_body2, integral_label + ", body 2", "linespoints", "pt 5 lw 2 lc rgb '#17becf'"));
  write_figure(folder, "patch_test", fig, run);
}

}  // namespace mortar
