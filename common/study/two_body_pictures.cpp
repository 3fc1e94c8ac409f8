#include "common/study/two_body_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/study/vtu.hpp"

namespace mortar {

namespace {
const char* body_colour(int l) { return l == 0 ? "lc rgb '#1f5f9f'" : "lc rgb '#a0522d'"; }

Mesh shifted(Mesh mesh, double dy) {
  for (auto& p : mesh.nodes) p.y() += dy;
  return mesh;
}

Series trace_nodes(const InterfaceTrace& trace, double y, const std::string& title, const std::string& extra) {
  Series s{title, trace.x, std::vector<double>(trace.x.size(), y), "points", extra};
  return s;
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
}  // namespace

Figure two_body_meshes(const TwoBodies& bodies, const ContactInterface& gamma, bool merged_grid,
                       const std::string& title) {
  const double L = gamma.nonmortar_trace.x.back() - gamma.nonmortar_trace.x.front();
  const double gap = 0.08 * L;  // body 1 lifted by this much: an exploded view
  Figure f;
  f.title = title;
  f.xlabel = "x [m]";
  f.ylabel = "y [m] (body 1 lifted by " + std::to_string(gap).substr(0, 4) + " m)";
  f.equal_axes = true;
  f.key = "outside right top";
  f.width = 1100;
  for (int l = 0; l < 2; ++l)
    f.series.push_back(mesh_edges(shifted(bodies.body(l).mesh, l == 0 ? gap : 0),
                                  "body " + std::to_string(l + 1), std::string(body_colour(l)) + " lw 1"));
  const bool body1_nonmortar = gamma.nonmortar == 0;
  const double y_nm = body1_nonmortar ? gap : 0, y_m = body1_nonmortar ? 0 : gap;
  f.series.push_back(trace_nodes(gamma.nonmortar_trace, y_nm, "xi^1: non-mortar nodes",
                                 "pt 7 ps 1.2 lc rgb '#000000'"));
  f.series.push_back(trace_nodes(gamma.mortar_trace, y_m, "xi^2: mortar nodes", "pt 5 ps 1.0 lc rgb '#cc0000'"));
  if (merged_grid) {
    Series s{"merged grid", gamma.grid.breakpoints, std::vector<double>(gamma.grid.breakpoints.size(), 0.5 * gap),
             "linespoints", "pt 2 ps 1.2 lw 1 lc rgb '#228b22'"};
    f.series.push_back(s);
  }
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
  char buf[64];
  std::snprintf(buf, sizeof buf, " (displacement x %g)", scale);
  f.title = title + buf;
  f.xlabel = "x [m]";
  f.ylabel = "y [m]";
  f.equal_axes = true;
  f.key = "outside right top";
  f.width = 1100;
  // body 1 lifted by the magnified gap, reference and deformed alike
  const auto lifted = [&](int l) {
    Mesh mesh = bodies.body(l).mesh;
    if (l == 0 && gap)
      for (auto& p : mesh.nodes) p.y() += scale * gap(p.x());
    return mesh;
  };
  if (gap) f.title += ", body 1 lifted by the gap g(x)";
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

void write_two_body_vtu(const std::string& folder, const TwoBodies& bodies, const Eigen::VectorXd& u,
                        const InterfaceCurve& pressure) {
  for (int l = 0; l < 2; ++l) {
    const Body& b = bodies.body(l);
    const Eigen::VectorXd ul = bodies.part(u, l);
    write_vtu(folder + "/body" + std::to_string(l + 1) + ".vtu", b.mesh, ul, element_stresses(b.mesh, b.material, ul));
  }
  write_curve_vtu(folder + "/contact.vtu", pressure.x, {{"pressure", pressure.value}});
}

}  // namespace mortar
