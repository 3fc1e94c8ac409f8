#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "study.hpp"
#include "wedge_exponent.hpp"
#include "common/contact/hertz_half_planes.hpp"
#include "common/study/contact_plots.hpp"
#include "common/study/plot.hpp"

namespace chapter10 {

namespace {

using mortar::Figure;
using mortar::Series;

std::string scene_label(const Options& o) {
  if (o.scene.name == "punch") return "punch (E1/E2 = " + std::to_string(static_cast<int>(std::lround(o.scene.bodies.E1 / o.scene.bodies.E2))) + ")";
  if (o.scene.name == "bilateral") return "bilateral manufactured scene";
  return "exact Hertz, a = L sqrt(2)/29";
}

// The window the zoom shows: the contact zone's edge (Hertz), the punch's left corner, or all.
std::array<double, 4> zoom_window(const Options& o) {
  const double L = o.scene.bodies.L;
  if (o.scene.name == "hertz-exact") {
    const double a = small_zone_half_width(L);
    return {L / 2 - 2.5 * a, L / 2 + 2.5 * a, -1.5 * a, 1.5 * a};
  }
  if (o.scene.name == "punch") {
    const double c = L / 2 - L / 8, d = L / 32;
    return {c - d, c + d, -d, d};
  }
  return {0, L, -o.scene.bodies.H2, o.scene.bodies.H1};
}

Figure mesh_panel(const MeshSnapshot& s, const std::string& title, const std::array<double, 4>* window) {
  Figure fig;
  fig.title = title;
  fig.xlabel = "x [m]";
  fig.ylabel = "y [m]";
  fig.equal_axes = true;
  fig.width = 800;
  fig.height = window ? 480 : 520;
  // the colours are named in the title: a key would cover the mesh or the axis
  fig.settings.push_back("set key off");
  fig.series.push_back(mortar::mesh_edges(s.mesh[0], "body 1", "lc rgb '#1f4e9c' lw 0.6"));
  fig.series.push_back(mortar::mesh_edges(s.mesh[1], "body 2", "lc rgb '#b2182b' lw 0.6"));
  if (window) {
    char range[160];
    std::snprintf(range, sizeof range, "set xrange [%.6g:%.6g]\nset yrange [%.6g:%.6g]", (*window)[0], (*window)[1],
                  (*window)[2], (*window)[3]);
    fig.settings.push_back(range);
  }
  return fig;
}

void plot_meshes(const Options& o, const LoopResult& a, bool run) {
  const auto window = zoom_window(o);
  for (const MeshSnapshot& s : a.snapshots) {
    const std::string counts = "body 1 (blue) " + std::to_string(s.mesh[0].triangles.size()) + " triangles, body 2 (red) " +
                               std::to_string(s.mesh[1].triangles.size());
    Figure fig = mesh_panel(s, "After " + std::to_string(s.step) + " adaptive steps, " + scene_label(o) + ": " + counts, nullptr);
    // the bilateral scene has no zone to zoom on
    if (o.scene.name != "bilateral")
      fig.panels.push_back(mesh_panel(
          s, o.scene.name == "punch" ? "zoom on body 1's left corner" : "zoom on the contact zone", &window));
    mortar::write_figure(o.out, "mesh_step_" + std::to_string(s.step), fig, run);
  }
}

// Each triangle filled by the decade of its error density eta_T^2 / |T| against the largest:
// where the error lives, whatever the triangles' sizes (the indicators themselves are nearly
// equal on an adapted mesh, which is what the marking aims at).
void plot_indicators(const Options& o, const LoopResult& a, bool run) {
  if (a.snapshots.empty()) return;
  const MeshSnapshot& s = a.snapshots.size() > 2 ? a.snapshots[2] : a.snapshots.back();
  std::array<std::vector<double>, 2> density;
  double top = 0;
  for (int l = 0; l < 2; ++l)
    for (std::size_t t = 0; t < s.eta2[l].size(); ++t) {
      density[l].push_back(s.eta2[l][t] / s.mesh[l].area(static_cast<int>(t)));
      top = std::max(top, density[l].back());
    }
  if (!(top > 0)) return;
  constexpr int classes = 6;
  Figure fig;
  fig.title = "Error density eta_T^2/|T| after " + std::to_string(s.step) + " steps: " + scene_label(o);
  fig.xlabel = "x [m]";
  fig.ylabel = "y [m]";
  fig.equal_axes = true;
  fig.key = "outside right top";
  fig.width = 1000;
  fig.height = 600;
  const char* colours[classes] = {"#b2182b", "#ef8a62", "#fddbc7", "#d1e5f0", "#67a9cf", "#2166ac"};
  for (int k = 0; k < classes; ++k) {
    char title[80];
    if (k + 1 < classes) std::snprintf(title, sizeof title, "within 10^{%d} of the largest", -(k + 1));
    else std::snprintf(title, sizeof title, "below 10^{%d} of it", -k);
    Series ser{title, {}, {}, "filledcurves closed", std::string("fc rgb '") + colours[k] + "' fs solid 1.0 noborder"};
    const double nan = std::nan("");
    for (int l = 0; l < 2; ++l)
      for (std::size_t t = 0; t < density[l].size(); ++t) {
        const double decades = -std::log10(std::max(density[l][t], 1e-300) / top);
        if (std::min(static_cast<int>(decades), classes - 1) != k) continue;
        for (int v : s.mesh[l].triangles[t]) {
          ser.x.push_back(s.mesh[l].nodes[v].x());
          ser.y.push_back(s.mesh[l].nodes[v].y());
        }
        ser.x.push_back(nan);
        ser.y.push_back(nan);
      }
    if (!ser.x.empty()) fig.series.push_back(ser);
  }
  fig.series.push_back(mortar::mesh_edges(s.mesh[0], "", "lc rgb '#555555' lw 0.3"));
  fig.series.push_back(mortar::mesh_edges(s.mesh[1], "", "lc rgb '#555555' lw 0.3"));
  mortar::write_figure(o.out, "indicators", fig, run);
}

Series run_series(const LoopResult& r, const std::string& y, const std::string& title, const std::string& extra) {
  Series s{title, {}, {}, "linespoints", extra};
  for (const StepRecord& k : r.steps) {
    s.x.push_back(k.dofs);
    s.y.push_back(y == "estimator" ? k.estimator / (k.err_energy / k.rel_err_energy)
                  : y == "effectivity" ? k.effectivity : k.rel_err_energy);
  }
  return s;
}

void plot_rates(const Options& o, const LoopResult& a, const LoopResult* u, bool run) {
  const bool exact = o.scene.name != "punch";
  Figure fig = mortar::log_log_figure(
      "Energy error and estimator against N: " + scene_label(o), "unknowns N",
      exact ? "relative to ||u|| (energy norm)" : "relative to ||u|| (energy norm, against the extrapolated energy)",
      "bottom left");
  fig.series.push_back(run_series(a, "error", "adaptive: error", "lc rgb '#1f4e9c' pt 7 lw 2"));
  fig.series.push_back(run_series(a, "estimator", "adaptive: estimator", "lc rgb '#1f4e9c' pt 6 dt 2 lw 2"));
  if (u) {
    fig.series.push_back(run_series(*u, "error", "uniform: error", "lc rgb '#b2182b' pt 5 lw 2"));
    fig.series.push_back(run_series(*u, "estimator", "uniform: estimator", "lc rgb '#b2182b' pt 4 dt 2 lw 2"));
  }
  fig.slopes.push_back({-0.5, 0, 0.5, "N^{-1/2}", ""});
  if (u && o.scene.name == "punch") {
    const double lambda = wedge_on_half_plane_exponent(
        dundurs_alpha(o.scene.bodies.E1, o.scene.bodies.nu1, o.scene.bodies.E2, o.scene.bodies.nu2), std::acos(-1.0) / 2);
    char label[64];
    std::snprintf(label, sizeof label, "N^{-%.3f} (corner theory)", lambda / 2);
    fig.slopes.push_back({-lambda / 2, 2, 0.5, label, ""});
  }
  mortar::write_figure(o.out, "error_vs_dofs", fig, run);
}

void plot_time(const Options& o, const LoopResult& a, const LoopResult* u, bool run) {
  Figure fig = mortar::log_log_figure("Energy error against wall time: " + scene_label(o), "wall time [s]",
                                      "relative energy error", "top right");
  Series s{"adaptive (every step so far)", {}, {}, "linespoints", "lc rgb '#1f4e9c' pt 7 lw 2"};
  for (const StepRecord& k : a.steps) {
    s.x.push_back(k.time_s);
    s.y.push_back(k.rel_err_energy);
  }
  fig.series.push_back(s);
  if (u) {
    Series v{"uniform (that level alone)", {}, {}, "linespoints", "lc rgb '#b2182b' pt 5 lw 2"};
    for (const StepRecord& k : u->steps) {
      v.x.push_back(k.time_s);
      v.y.push_back(k.rel_err_energy);
    }
    fig.series.push_back(v);
  }
  fig.series.push_back({"1 %", {1e-3, 1e4}, {0.01, 0.01}, "lines", "lc rgb '#888888' dt 3"});
  fig.settings.push_back("set xrange [*:*]");
  mortar::write_figure(o.out, "error_vs_time", fig, run);
}

void plot_effectivity(const Options& o, const LoopResult& a, const LoopResult* u, bool run) {
  if (o.scene.name == "punch") return;
  Figure fig;
  fig.title = "Effectivity eta / ||u - u_h|| against N: " + scene_label(o);
  fig.xlabel = "unknowns N";
  fig.ylabel = "effectivity index";
  fig.log_x = true;
  fig.key = "bottom right";
  fig.series.push_back(run_series(a, "effectivity", "adaptive", "lc rgb '#1f4e9c' pt 7 lw 2"));
  if (u) fig.series.push_back(run_series(*u, "effectivity", "uniform", "lc rgb '#b2182b' pt 5 lw 2"));
  fig.settings.push_back("set yrange [0:*]");
  mortar::write_figure(o.out, "effectivity", fig, run);
}

// The pressure on the last adaptive mesh: beside Hertz's at the zone's right edge, or against
// the distance to the punch's corner on log axes.
void plot_edge_pressure(const Options& o, const LoopResult& a, const Scene& scene, bool run) {
  const mortar::InterfaceCurve& p = a.last->pressure;
  if (o.scene.name == "hertz-exact") {
    const auto* hertz = static_cast<const mortar::HertzHalfPlanes*>(scene.exact());
    const double edge = hertz->centre() + hertz->half_width(), d = 0.25 * hertz->half_width();
    Figure fig;
    fig.title = "Pressure at the zone's edge on the last adaptive mesh (" + std::to_string(a.steps.back().dofs) + " unknowns)";
    fig.xlabel = "x [m]";
    fig.ylabel = "contact pressure [Pa]";
    fig.key = "top right";
    Series exact{"Hertz, exact", {}, {}, "lines", "lc rgb '#aaaaaa' lw 6"};
    for (int k = 0; k <= 400; ++k) {
      const double x = edge - d + 2 * d * k / 400;
      exact.x.push_back(x);
      exact.y.push_back(hertz->pressure(x));
    }
    Series nodes{"lambda_i at the non-mortar nodes", {}, {}, "linespoints", "lc rgb '#1f4e9c' pt 7 ps 0.8"};
    for (std::size_t k = 0; k < p.x.size(); ++k)
      if (std::fabs(p.x[k] - edge) <= d) {
        nodes.x.push_back(p.x[k]);
        nodes.y.push_back(p.value[k]);
      }
    fig.series = {exact, nodes};
    mortar::write_figure(o.out, "edge_pressure", fig, run);
  } else if (o.scene.name == "punch") {
    const double corner = o.scene.bodies.L / 2 - o.scene.bodies.L / 8;
    const double lambda = wedge_on_half_plane_exponent(
        dundurs_alpha(o.scene.bodies.E1, o.scene.bodies.nu1, o.scene.bodies.E2, o.scene.bodies.nu2), std::acos(-1.0) / 2);
    Figure fig = mortar::log_log_figure("Pressure near the punch's corner on the last adaptive mesh",
                                        "distance r to the corner [m]", "contact pressure [Pa]", "top right");
    Series nodes{"lambda_i at the non-mortar nodes (left half)", {}, {}, "points", "lc rgb '#1f4e9c' pt 7 ps 0.6"};
    for (std::size_t k = 0; k < p.x.size(); ++k) {
      const double r = p.x[k] - corner;
      if (r > 0 && r <= o.scene.bodies.L / 8 && p.value[k] > 0) {
        nodes.x.push_back(r);
        nodes.y.push_back(p.value[k]);
      }
    }
    fig.series.push_back(nodes);
    char label[64];
    std::snprintf(label, sizeof label, "r^{%.3f} (wedge theory)", lambda - 1);
    // through the farthest node, raised by half: drawn above the points it is compared with
    fig.slopes.push_back({lambda - 1, 0, -0.5, label, "", true});
    mortar::write_figure(o.out, "edge_pressure", fig, run);
  }
}

}  // namespace

void write_figures(const Options& o, const LoopResult& adaptive, const LoopResult* uniform, const Scene& scene,
                   bool run_gnuplot) {
  plot_meshes(o, adaptive, run_gnuplot);
  plot_indicators(o, adaptive, run_gnuplot);
  plot_rates(o, adaptive, uniform, run_gnuplot);
  plot_time(o, adaptive, uniform, run_gnuplot);
  plot_effectivity(o, adaptive, uniform, run_gnuplot);
  plot_edge_pressure(o, adaptive, scene, run_gnuplot);
}

}  // namespace chapter10
