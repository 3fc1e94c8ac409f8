#include "hertz_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/fem/mesh.hpp"
#include "common/timing/stopwatch.hpp"
#include "hertz.hpp"
#include "peak_pressure.hpp"

namespace chapter05 {

namespace {
// The first solve that locates the contact zone: uniform square cells, this many along Gamma_c.
constexpr int presolve_cells = 64;
// Each locating pass divides the h_edge of the previous one by this factor.
constexpr double zoom = 4;

UnilateralSetup reference_setup(const Options& o) {
  UnilateralSetup s;
  s.matching = mortar::Matching::integral;
  s.nonmortar = 0;
  s.solver = solver_options(o, "pdas", true);
  s.scene = {"hertz", o.L, o.R, o.delta};
  s.measure_limit = false;  // the reference is not part of any level's time
  return s;
}

// The bracket of each edge in a discrete contact set: the outermost node in contact and its
// neighbour out of contact. The true edge lies in it or within half an element of it (largest
// `edge_offset_elements` seen: 0.47), which is why graded_bodies widens it by half on each side.
ZoneEdges edges_of(const mortar::ContactZone& z) {
  if (z.empty) throw std::runtime_error("Hertz reference: the bodies do not touch");
  return {z.left_inactive, z.left_active, z.right_active, z.right_inactive};
}

mortar::ContactZone presolve_zone(const Options& o, const mortar::ExactContact& exact, int cells) {
  UnilateralSetup s = reference_setup(o);
  s.geometry.L = o.L;
  s.geometry.H1 = o.H1;
  s.geometry.H2 = o.H2;
  s.geometry.n1 = s.geometry.n2 = cells;
  s.geometry.m1 = std::max(1, static_cast<int>(std::lround(cells * o.H1 / o.L)));
  s.geometry.m2 = std::max(1, static_cast<int>(std::lround(cells * o.H2 / o.L)));
  return solve_unilateral_level(s, exact).zone;
}

Estimate estimate(double fine, double coarse) {
  return {fine, fine != 0 ? std::fabs(fine - coarse) / std::fabs(fine) : 0.0};
}

// The reference against half-space Hertz at the reference's own force (hertz.hpp).
void measure_model_error(const Options& o, HertzReference& ref) {
  const Hertz h = hertz_at_force(o.E1, o.nu1, o.E2, o.nu2, o.R, ref.force.value);
  const auto p = [&](double x) { return h.pressure(x - o.L / 2); };
  const double norm = mortar::l2_norm(ref.pressure, p);
  ref.model_pressure = norm > 0 ? mortar::l2_error(ref.pressure, p) / norm : 0.0;
  ref.model_peak = h.peak_pressure() > 0 ? ref.peak.value / h.peak_pressure() - 1 : 0.0;
  ref.model_half_width = h.half_width() > 0 ? ref.half_width.value / h.half_width() - 1 : 0.0;
}

// Both bodies on one graded x grid (matching traces), each graded towards Gamma_c in y.
mortar::TwoBodies graded_bodies(const Options& o, const mortar::ExactContact& exact,
                                const ZoneEdges& e, const ReferenceGrading& g) {
  // a cell size growing linearly with the distance d: cells grow geometrically, by 1 + growth
  const auto size = [&g](double d, double cap) { return std::min(cap, g.h_edge + g.growth * d); };
  // the bracket of each edge, widened by half a bracket on both sides
  const double margin_left = 0.5 * (e.left_inner - e.left_outer), margin_right = 0.5 * (e.right_outer - e.right_inner);
  const auto x_size = [&](double x) {
    const double d_left = std::max({0.0, e.left_outer - margin_left - x, x - e.left_inner - margin_left});
    const double d_right = std::max({0.0, e.right_inner - margin_right - x, x - e.right_outer - margin_right});
    const bool inside = x > e.left_inner && x < e.right_inner;
    return size(std::min(d_left, d_right), inside ? g.h_zone : g.h_max);
  };
  mortar::RectangleSpec upper, lower;
  upper.x1 = lower.x1 = o.L;
  upper.x_nodes = lower.x_nodes = mortar::graded_nodes(0, o.L, x_size);
  upper.y0 = 0;
  upper.y1 = o.H1;
  upper.y_nodes = mortar::graded_nodes(0, o.H1, [&](double y) { return size(y, g.h_max); });
  lower.y0 = -o.H2;
  lower.y1 = 0;
  lower.y_nodes = mortar::graded_nodes(-o.H2, 0, [&](double y) { return size(-y, g.h_max); });
  return mortar::TwoBodies({mortar::rectangle_mesh(upper), exact.material(0)},
                           {mortar::rectangle_mesh(lower), exact.material(1)});
}

// The P1 curve c at the points x (a superset of its own breakpoints): the same function.
std::vector<double> values_at(const mortar::InterfaceCurve& c, const std::vector<double>& x) {
  std::vector<double> v;
  v.reserve(x.size());
  std::size_t e = 0;
  for (double t : x) {
    while (e + 2 < c.x.size() && c.x[e + 1] < t) ++e;
    const double s = std::clamp((t - c.x[e]) / (c.x[e + 1] - c.x[e]), 0.0, 1.0);
    v.push_back((1 - s) * c.value[e] + s * c.value[e + 1]);
  }
  return v;
}
}  // namespace

UnilateralLevel solve_graded(const Options& o, const mortar::ExactContact& exact,
                             const ZoneEdges& edges, const ReferenceGrading& g) {
  return solve_unilateral_level(graded_bodies(o, exact, edges, g), reference_setup(o), exact);
}

ReferenceGrading reference_grading(const Options& o) {
  // the finest level's smaller mesh size along Gamma_c
  const double h1 = o.L / (static_cast<double>(o.n0) * (1 << (o.levels - 1)));
  const double h = std::min(h1, h1 * o.h_ratio);
  return {h / 32, 0.2, h, 2 * h};
}

double relative_l2_distance_on(const mortar::InterfaceCurve& p, const mortar::InterfaceCurve& q,
                               double lo, double hi) {
  std::vector<double> x = p.x;
  x.insert(x.end(), q.x.begin(), q.x.end());
  x.push_back(std::clamp(lo, q.x.front(), q.x.back()));
  x.push_back(std::clamp(hi, q.x.front(), q.x.back()));
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  // both are P1 on the union: the difference is P1 there, and 4-point Gauss is exact
  const mortar::InterfaceCurve p_union{x, values_at(p, x)}, q_union{x, values_at(q, x)};
  const auto q_of = [&](double t) {
    const auto it = std::upper_bound(x.begin(), x.end(), t);
    const std::size_t e = std::clamp<std::size_t>(it - x.begin(), 1, x.size() - 1) - 1;
    const double s = (t - x[e]) / (x[e + 1] - x[e]);
    return (1 - s) * q_union.value[e] + s * q_union.value[e + 1];
  };
  const double norm = mortar::l2_norm(q_union, q_of);
  // the pieces of the union inside (lo, hi)
  mortar::InterfaceCurve inside;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (x[k] >= lo && x[k] <= hi) {
      inside.x.push_back(x[k]);
      inside.value.push_back(p_union.value[k]);
    }
  return norm > 0 && inside.x.size() > 1 ? mortar::l2_error(inside, q_of) / norm : 0.0;
}

double relative_l2_distance(const mortar::InterfaceCurve& p, const mortar::InterfaceCurve& q) {
  return relative_l2_distance_on(p, q, q.x.front(), q.x.back());
}

double edge_offset_in_elements(const mortar::ContactZone& level, const mortar::ContactZone& reference, double h) {
  if (level.empty && reference.empty) return 0.0;
  if (level.empty || reference.empty) {
    const mortar::ContactZone& z = level.empty ? reference : level;
    return (z.right_active - z.left_active) / h;
  }
  // distance between the intervals [lo1, hi1] and [lo2, hi2], over the length of the first
  // (or h where the first is a single node, at an end of Gamma_c)
  const auto offset = [h](double lo1, double hi1, double lo2, double hi2) {
    return std::max({0.0, lo1 - hi2, lo2 - hi1}) / (hi1 > lo1 ? hi1 - lo1 : h);
  };
  return std::max(offset(level.left_inactive, level.left_active, reference.left_inactive, reference.left_active),
                  offset(level.right_active, level.right_inactive, reference.right_active, reference.right_inactive));
}

HertzReference make_hertz_reference(const Options& o, const mortar::ExactContact& exact,
                                    const ReferenceGrading& grading) {
  const mortar::Stopwatch clock;
  HertzReference ref;
  ref.grading = grading;
  // A zone narrower than the pre-solve's elements may not show on it: refine the pre-solve
  // until it is as fine as the levels before concluding that the bodies do not touch.
  int cells = presolve_cells;
  mortar::ContactZone first = presolve_zone(o, exact, cells);
  while (first.empty && o.L / cells > grading.h_zone)  // h_zone is the finest level's h
    first = presolve_zone(o, exact, cells *= 2);
  if (first.empty) {  // no contact: a zero pressure, and every error against it is 0
    ref.pressure = {{0, o.L}, {0, 0}};
    ref.time_s = clock.seconds();
    return ref;
  }
  // Locate the edges: each pass puts its fine cells where the previous one found them, so the
  // two references need fine cells only over a few of their own elements.
  const ReferenceGrading coarse = grading.doubled();
  ZoneEdges edges = edges_of(first);
  ReferenceGrading locate{o.L / cells / zoom, coarse.growth, o.L / cells, o.L / cells};
  for (; locate.h_edge > zoom * coarse.h_edge; locate.h_edge /= zoom, ++ref.passes)
    edges = edges_of(solve_graded(o, exact, edges, locate).zone);
  ref.coarse = std::make_unique<UnilateralLevel>(solve_graded(o, exact, edges, coarse));
  ref.fine = std::make_unique<UnilateralLevel>(solve_graded(o, exact, edges_of(ref.coarse->zone), grading));
  const UnilateralLevel &f = *ref.fine, &c = *ref.coarse;
  ref.pressure = f.pressure;
  ref.zone = f.zone;
  ref.force = estimate(f.total_force, c.total_force);
  ref.half_width = estimate(f.zone.half_width(), c.zone.half_width());
  ref.peak = estimate(peak_pressure(f.pressure, o.L / 2), peak_pressure(c.pressure, o.L / 2));
  ref.pressure_change = relative_l2_distance(c.pressure, f.pressure);
  measure_model_error(o, ref);
  ref.time_s = clock.seconds();
  return ref;
}

}  // namespace chapter05
