#include "common/study/two_body_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "common/study/vtu.hpp"

namespace mortar {

namespace {
const char* body_colour(int l) { return l == 0 ? "lc rgb '#1f5f9f'" : "lc rgb '#a0522d'"; }

Mesh shifted(Mesh mesh, double dy) {
  for (auto& p : mesh.nodes) p.y() += dy;
  return mesh;
}

// A number line at height y with a tick at every node: a horizontal line, then one short
// vertical stroke per node (NaN between strokes breaks the line).
Series node_line(const std::vector<double>& x, double y, double tick, const std::string& title,
                 const std::string& extra) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Series s{title, {x.front(), x.back(), nan}, {y, y, nan}, "lines", extra};
  for (double xi : x) {
    s.x.insert(s.x.end(), {xi, xi, nan});
    s.y.insert(s.y.end(), {y - tick, y + tick, nan});
  }
  return s;
}

Series points_at(const std::vector<double>& x, double y, const std::string& title, const std::string& extra) {
  return Series{title, x, std::vector<double>(x.size(), y), "points", extra};
}

double largest_displacement(const Eigen::VectorXd& u) {
  double m = 0;
  for (Eigen::Index a = 0; a + 1 < u.size(); a += 2) m = std::max(m, std::hypot(u[a], u[a + 1]));
  return m;
}

// 1, 2 or 5 times a power of ten, the largest not above x: a factor a reader can repeat.
double round_factor(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double f : {5.0, 2.0, 1.0})
    if (f * p <= x) return f * p;
  return p;
}

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g m", v);
  return buf;
}
}  // namespace

Figure two_body_meshes(const TwoBodies& bodies, const ContactInterface& gamma, Matching matching,
                       const std::string& title) {
  const double L = gamma.nonmortar_trace.length();
  const double lift = 0.05 * L;  // body 1 lifted: an exploded view of Gamma_c
  double bottom = 0;             // the lowest point of body 2
  for (const auto& p : bodies.body(1).mesh.nodes) bottom = std::min(bottom, p.y());
  const double row = 0.07 * L, tick = 0.018 * L;  // the strip's rows below body 2
  const bool integral = matching == Matching::integral;

  Figure f;
  f.title = title + ": the meshes of the coarsest level and their traces on Gamma_c";
  f.xlabel = "x [m]";
  f.ylabel = "y [m] (body 1 lifted by " + metres(lift) + "; below: the traces on Gamma_c)";
  f.equal_axes = true;
  f.key = "above";  // not beside: tall bodies (chapter 5) keep their title inside the canvas
  f.width = 1000;
  f.height = 950;
  for (int l = 0; l < 2; ++l)
    f.series.push_back(mesh_edges(shifted(bodies.body(l).mesh, l == 0 ? lift : 0),
                                  "body " + std::to_string(l + 1), std::string(body_colour(l)) + " lw 1"));
  // the trace nodes on the bodies themselves
  const int nm = gamma.nonmortar;
  const double y_nm = nm == 0 ? lift : 0, y_m = nm == 0 ? 0 : lift;
  const std::string xi1 = integral ? "xi^1: non-mortar nodes, M_h^1 lives here"
                                   : "xi^1: non-mortar nodes, one pointwise row each";
  // the trace nodes: element end points, and for P2 the midpoints between them
  const std::vector<double> x_nm = gamma.nonmortar_trace.node_positions(), x_m = gamma.mortar_trace.node_positions();
  f.series.push_back(points_at(x_nm, y_nm, xi1, "pt 7 ps 1.3 lc rgb '#000000'"));
  f.series.push_back(points_at(x_m, y_m, "xi^2: mortar nodes", "pt 4 ps 1.3 lc rgb '#cc0000'"));
  if (!integral) {
    // each pointwise row reads u^2 at x_a, between two mortar nodes: a dotted link from a to
    // the mortar trace
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Series links{"the row of a: u^2 interpolated at x_a", {}, {}, "linespoints", "dt 3 pt 2 ps 0.8 lc rgb '#555555'"};
    for (double x : x_nm) {
      links.x.insert(links.x.end(), {x, x, nan});
      links.y.insert(links.y.end(), {y_nm, y_m, nan});
    }
    f.series.push_back(links);
  }
  // the strip: the same nodes on number lines, then the merged grid
  f.series.push_back(node_line(x_nm, bottom - row, tick, "strip: xi^1", "lw 2 lc rgb '#000000'"));
  f.series.push_back(node_line(x_m, bottom - 2 * row, tick, "strip: xi^2", "lw 2 lc rgb '#cc0000'"));
  if (integral)
    f.series.push_back(node_line(gamma.grid.breakpoints, bottom - 3 * row, tick,
                                 gamma.nonmortar_trace.degree == 1
                                     ? "strip: merged grid (every node of xi^1 and xi^2)"
                                     : "strip: merged grid (every element end of xi^1 and xi^2)",
                                 "lw 2 lc rgb '#228b22'"));
  return f;
}

Figure deformed_two_bodies(const TwoBodies& bodies, const Eigen::VectorXd& u, const std::string& title,
                           const std::function<double(double)>& gap) {
  double xmin = 0, xmax = 0;
  for (const auto& p : bodies.body(0).mesh.nodes) xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
  const double L = xmax - xmin;
  const double umax = largest_displacement(u);
  const double scale = umax > 0 ? round_factor(0.05 * std::fabs(L) / umax) : 1;
  Figure f;
  char buf[96];
  std::snprintf(buf, sizeof buf, ": deformed, u_h x %g (max |u_h| = %.3g m)", scale, umax);
  f.title = title + buf;
  f.xlabel = "x [m]";
  f.ylabel = "y [m]";
  f.equal_axes = true;
  f.key = "above";  // not beside: tall bodies (chapter 5) keep their title inside the canvas
  f.width = 1000;
  f.height = 950;
  // body 1 lifted by the magnified gap, reference and deformed alike
  const auto lifted = [&](int l) {
    Mesh mesh = bodies.body(l).mesh;
    if (l == 0 && gap)
      for (auto& p : mesh.nodes) p.y() += scale * gap(p.x());
    return mesh;
  };
  if (gap) f.title += ", body 1 lifted by g(x)";
  for (int l = 0; l < 2; ++l)
    f.series.push_back(mesh_edges(lifted(l), l == 0 ? "reference" : "", "lc rgb '#c8c8c8' lw 1"));
  for (int l = 0; l < 2; ++l) {
    Mesh moved = lifted(l);
    const Eigen::VectorXd ul = bodies.part(u, l);
    for (std::size_t a = 0; a < moved.nodes.size(); ++a) moved.nodes[a] += scale * Eigen::Vector2d(ul[2 * a], ul[2 * a + 1]);
    f.series.push_back(mesh_edges(moved, "body " + std::to_string(l + 1) + ", deformed", std::string(body_colour(l)) + " lw 1"));
  }
  return f;
}

std::vector<double> curve_at(const InterfaceCurve& curve, const std::vector<double>& x) {
  if (curve.x.size() < 2 || curve.value.size() != curve.x.size())
    throw std::invalid_argument("curve_at: the curve needs two points or more, one value each");
  // the curve's pieces as a 1D grid of its degree, its points the grid's nodes
  InterfaceTrace trace;
  trace.degree = curve.degree;
  for (std::size_t k = 0; k < curve.x.size(); k += static_cast<std::size_t>(curve.degree)) trace.x.push_back(curve.x[k]);
  std::vector<double> out;
  out.reserve(x.size());
  for (double xi : x) out.push_back(trace.evaluate(curve.value, xi));
  return out;
}

void write_two_body_vtu(const std::string& folder, const TwoBodies& bodies, const Eigen::VectorXd& u,
                        const InterfaceCurve& pressure, const InterfaceCurve& jump) {
  for (int l = 0; l < 2; ++l) {
    const Body& b = bodies.body(l);
    write_vtu(folder + "/body" + std::to_string(l + 1) + ".vtu", body_grid(b.mesh, b.material, bodies.part(u, l)),
              VtuFormat::binary);
  }
  write_curve_vtu(folder + "/contact.vtu", jump.x,
                  {{"pressure", curve_at(pressure, jump.x)}, {"normal_jump", jump.value}}, VtuFormat::binary);
}

}  // namespace mortar
