#include "transfer_case.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/interface/merged_grid.hpp"
#include "common/interface/mortar_matrices.hpp"
#include "common/interface/multiplier_space.hpp"
#include "common/fem/quadrature.hpp"
#include "common/linalg/spd_solver.hpp"
#include "common/timing/stopwatch.hpp"
#include "common/interface/trace_transfer.hpp"

namespace chapter01 {

int side2_elements(int n1, double ratio) {
  const double n2 = std::round(n1 / ratio);
  if (!(n2 <= std::numeric_limits<int>::max()))
    throw std::invalid_argument("side2_elements: " + std::to_string(n1) + " / " +
                                std::to_string(ratio) + " elements do not fit an int");
  return std::max(1, static_cast<int>(n2));
}

bool nested(const mortar::InterfaceTrace& coarse, const mortar::InterfaceTrace& fine) {
  const double tol = 1e-12 * fine.length();
  for (double x : coarse.x) {
    const int e = fine.element_containing(x);
    if (std::fabs(fine.x[e] - x) > tol && std::fabs(fine.x[e + 1] - x) > tol) return false;
  }
  return true;
}

namespace {
constexpr int repeats = 5;  // microsecond timings: keep the best of five for both clocks

// Integral of f over the piece [p, q] with 5-point Gauss. Where an end of the piece is an edge
// of w (w like sqrt(distance) there) the substitution x = end +- (q - p) s^2 makes the
// integrand smooth in s again; a piece with an edge at both ends is split in two first.
double integrate_piece(double p, double q, const TraceFunction& w, const std::function<double(double)>& f) {
  const mortar::SegmentRule g = mortar::gauss_legendre(5);
  const std::vector<double> edges = w.edges();
  const auto is_edge = [&](double x) { return std::find(edges.begin(), edges.end(), x) != edges.end(); };
  if (is_edge(p) && is_edge(q))
    return integrate_piece(p, 0.5 * (p + q), w, f) + integrate_piece(0.5 * (p + q), q, w, f);
  double sum = 0;
  for (std::size_t k = 0; k < g.points.size(); ++k) {
    const double s = g.points[k], len = q - p;
    if (is_edge(p)) sum += g.weights[k] * 2 * len * s * f(p + len * s * s);
    else if (is_edge(q)) sum += g.weights[k] * 2 * len * s * f(q - len * s * s);
    else sum += g.weights[k] * len * f(p + len * s);
  }
  return sum;
}

// Errors of a nodal P1 function w1 on trace 1 against w, on each element split at the kinks
// and edges of w, so every piece is smooth (after the substitution at an edge). Relative
// errors are computed in x / L, so no L between 1e-6 and 1e6 under- or overflows. With edges
// w' is not square integrable: the H1 errors are NaN (reported as null).
TransferErrors errors_against(const mortar::InterfaceTrace& t1, const std::vector<double>& w1,
                              const TraceFunction& w, double integral_w2) {
  std::vector<double> breaks = w.kinks;
  for (double x : w.edges()) breaks.push_back(x);
  double e_l2 = 0, e_h1 = 0, n_l2 = 0, n_h1 = 0;
  for (int e = 0; e < t1.num_elements(); ++e) {
    const double a = t1.x[e], b = t1.x[e + 1], slope = (w1[e + 1] - w1[e]) / (b - a);
    std::vector<double> cuts = {a};
    for (double k : breaks)
      if (k > a && k < b) cuts.push_back(k);
    std::sort(cuts.begin() + 1, cuts.end());
    cuts.push_back(b);
    const auto wh = [&](double x) { return w1[e] + slope * (x - a); };
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
      const auto piece = [&](const std::function<double(double)>& f) {
        return integrate_piece(cuts[p], cuts[p + 1], w, f) / w.L;
      };
      e_l2 += piece([&](double x) { return std::pow(wh(x) - w.value(x), 2); });
      n_l2 += piece([&](double x) { return std::pow(w.value(x), 2); });
      if (w.has_edges()) continue;
      e_h1 += piece([&](double x) { return std::pow(w.L * (slope - w.derivative(x)), 2); });
      n_h1 += piece([&](double x) { return std::pow(w.L * w.derivative(x), 2); });
    }
  }
  TransferErrors out;
  out.l2 = std::sqrt(e_l2 / n_l2);
  out.h1 = w.has_edges() ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(e_h1 / n_h1);
  out.integral_rel_error = std::fabs(mortar::integral(t1, w1) - integral_w2) / std::fabs(integral_w2);
  return out;
}

}  // namespace

TransferResult run_transfer_case(const TransferCase& c, const TraceFunction& w) {
  TransferResult r;
  r.trace1 = mortar::uniform_trace(w.L, c.n1, c.jitter, 1);
  r.trace2 = mortar::uniform_trace(w.L, c.n2, c.jitter, 2);
  for (double x : r.trace2.x) r.w2.push_back(w.value(x));

  r.pointwise = mortar::pointwise_transfer(r.trace1, r.trace2, r.w2);
  // The mortar projection, timed against the 1D floor: an L2 projection onto side 1's own
  // grid, i.e. assemble the P1 mass matrix of trace 1 and solve with it once. The mortar
  // projection cannot do less work than this. Microsecond timings: the best of five of each.
  r.timing = mortar::time_against_limit(
      [&] {
        mortar::MergedGrid grid;
        mortar::MultiplierSpace space;
        mortar::MortarMatrices mm;
        {
          const mortar::ProfilePhase phase("merged grid");
          grid = mortar::merge_traces(r.trace1, r.trace2);
        }
        {
          const mortar::ProfilePhase phase("multiplier space");
          space = mortar::end_modified_p1(r.trace1);
        }
        {
          const mortar::ProfilePhase phase("mortar matrices D and M");
          mm = mortar::mortar_matrices(r.trace1, r.trace2, grid, space);
        }
        const mortar::ProfilePhase phase("projection D^-1 M w");
        r.mortar = mortar::mortar_projection(r.trace1, r.trace2, mm, r.w2);
      },
      [&] { return r.trace1.mass_matrix(); }, {repeats, repeats, 0});
  r.time_s = r.timing.time_s;
  r.limit_s = r.timing.limit_s;

  const double integral_w2 = mortar::integral(r.trace2, r.w2);
  r.pointwise_errors = errors_against(r.trace1, r.pointwise, w, integral_w2);
  r.mortar_errors = errors_against(r.trace1, r.mortar, w, integral_w2);
  return r;
}

}  // namespace chapter01
