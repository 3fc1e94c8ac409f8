#include "common/contact/pressure_norms.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/fem/lagrange_1d.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

namespace {
// Each piece of an element gets a 5-point Gauss rule, and each element is cut into 4 pieces,
// and at every breakpoint of p_h and every kink of p inside it. Next to a kink (the edge of a
// contact zone, where p behaves like sqrt(|x - k|)) the variable x = k +- d s^2 turns the square
// root into a smooth function of s, so the rule keeps its order there too.
constexpr int pieces_per_element = 4;
constexpr int gauss_points = 5;

// Calls add(x, w) for a rule on [left, right]; a kink at one end is graded away by x = k +- d s^2.
template <class Add>
void graded_rule(double left, double right, bool kink_left, bool kink_right, const Add& add) {
  static const SegmentRule rule = gauss_legendre(gauss_points);
  if (kink_left && kink_right) {
    const double middle = 0.5 * (left + right);
    graded_rule(left, middle, true, false, add);
    graded_rule(middle, right, false, true, add);
    return;
  }
  const double d = right - left, h = 1.0 / pieces_per_element;
  for (int piece = 0; piece < pieces_per_element; ++piece)
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double t = (piece + rule.points[q]) * h, w = rule.weights[q] * h;  // t in (0, 1)
      if (kink_left)
        add(left + d * t * t, 2 * d * t * w);
      else if (kink_right)
        add(right - d * t * t, 2 * d * t * w);
      else
        add(left + d * t, d * w);
    }
}

// Calls add(x, w) for the points x and weights w of a composite rule on [a, b], cut at the given
// interior points, of which those in the sorted list kinks are kinks of the integrand.
template <class Add>
void composite_rule(double a, double b, std::vector<double> cuts, const std::vector<double>& kinks, const Add& add) {
  cuts.insert(cuts.begin(), a);
  cuts.push_back(b);
  const auto is_kink = [&](double x) { return std::binary_search(kinks.begin(), kinks.end(), x); };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    graded_rule(cuts[k], cuts[k + 1], is_kink(cuts[k]), is_kink(cuts[k + 1]), add);
}

// p_h between its points, P1 or P2 (contact_fields.hpp); its piece ends strictly inside (a, b).
struct CurveReader {
  const InterfaceCurve& curve;
  std::vector<double> ends;  // the points where a piece ends: all of them for P1, every other for P2

  explicit CurveReader(const InterfaceCurve& c) : curve(c) {
    for (std::size_t k = 0; k < c.x.size(); k += static_cast<std::size_t>(c.degree)) ends.push_back(c.x[k]);
  }
  double operator()(double x) const {
    const auto it = std::upper_bound(ends.begin(), ends.end(), x);
    const std::size_t e = std::clamp<std::size_t>(static_cast<std::size_t>(it - ends.begin()), 1, ends.size() - 1) - 1;
    return curve.at(static_cast<int>(e), (x - ends[e]) / (ends[e + 1] - ends[e]));
  }
  std::vector<double> breakpoints_inside(double a, double b) const { return points_inside(ends, a, b); }

  // the points of a sorted list strictly inside (a, b)
  static std::vector<double> points_inside(const std::vector<double>& sorted, double a, double b) {
    const auto first = std::upper_bound(sorted.begin(), sorted.end(), a);
    const auto last = std::lower_bound(sorted.begin(), sorted.end(), b);
    return first < last ? std::vector<double>(first, last) : std::vector<double>{};
  }
};

// The cuts of element (a, b): the breakpoints of p_h and the kinks of p inside it, in order
std::vector<double> cuts_inside(const CurveReader& reader, const std::vector<double>& sorted_kinks, double a,
                                double b) {
  std::vector<double> cuts = reader.breakpoints_inside(a, b);
  const std::vector<double> kinks = CurveReader::points_inside(sorted_kinks, a, b);
  cuts.insert(cuts.end(), kinks.begin(), kinks.end());
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

std::vector<double> sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v;
}

void check_curve(const InterfaceCurve& c, const InterfaceTrace& t) {
  if (c.x.size() < 2 || c.x.size() != c.value.size() || (c.x.size() - 1) % c.degree != 0)
    throw std::invalid_argument("pressure_errors: p_h needs at least 2 points and one value per point, got " +
                                std::to_string(c.x.size()) + " points and " + std::to_string(c.value.size()) +
                                " values (degree " + std::to_string(c.degree) + ")");
  for (std::size_t i = 0; i + 1 < c.x.size(); ++i)
    if (!(c.x[i + 1] > c.x[i]))
      throw std::invalid_argument("pressure_errors: the points of p_h must increase, x[" + std::to_string(i + 1) +
                                  "] = " + std::to_string(c.x[i + 1]) + " after " + std::to_string(c.x[i]));
  const double tol = 1e-12 * t.length();
  if (std::fabs(c.x.front() - t.x.front()) > tol || std::fabs(c.x.back() - t.x.back()) > tol)
    throw std::invalid_argument("pressure_errors: p_h spans [" + std::to_string(c.x.front()) + ", " +
                                std::to_string(c.x.back()) + "], the non-mortar trace [" +
                                std::to_string(t.x.front()) + ", " + std::to_string(t.x.back()) + "]");
}

// ||p - p_h||^2_{L2(e)} for every element e of the non-mortar trace, as scale^2 * squares[e].
// A pressure scales with E, and its square overflows at E = 1e300 and underflows at E = 1e-160:
// the differences are divided by the largest of them before squaring.
struct ElementSquares {
  double scale = 0;  // the largest |p - p_h| at the quadrature points
  std::vector<double> squares;
};
ElementSquares element_squares(const InterfaceTrace& t, const InterfaceCurve& p_h,
                               const std::function<double(double)>& p, const std::vector<double>& kinks) {
  const CurveReader reader{p_h};
  std::vector<std::vector<std::pair<double, double>>> points(static_cast<std::size_t>(t.num_elements()));
  ElementSquares s;
  bool nan = false;
  for (int e = 0; e < t.num_elements(); ++e)
    composite_rule(t.x[e], t.x[e + 1], cuts_inside(reader, kinks, t.x[e], t.x[e + 1]), kinks, [&](double x, double w) {
      const double d = p(x) - reader(x);
      nan = nan || std::isnan(d);
      s.scale = std::max(s.scale, std::fabs(d));
      points[e].push_back({d, w});
    });
  if (nan) s.scale = std::nan("");  // passed on, not hidden
  s.squares.assign(points.size(), 0.0);
  if (!(s.scale > 0) || std::isinf(s.scale)) return s;
  for (std::size_t e = 0; e < points.size(); ++e)
    for (const auto& [d, w] : points[e]) s.squares[e] += w * (d / s.scale) * (d / s.scale);
  return s;
}

// The norms of one error, from its element squares: whole, interior, ends, mesh-dependent.
struct SplitNorms {
  double whole = 0, interior = 0, ends = 0, hminus = 0;
};
SplitNorms split_norms(const InterfaceTrace& t, const ElementSquares& error) {
  const int N = t.num_elements();
  const std::vector<double>& squares = error.squares;
  if (!(error.scale > 0) || std::isinf(error.scale)) return {error.scale, error.scale, error.scale, error.scale};
  SplitNorms s;
  for (int e = 0; e < N; ++e) {
    const bool end = e == 0 || e == N - 1;  // where M_h^1 is constant (paper: a1 or a2 in T)
    (end ? s.ends : s.interior) += squares[e];
    s.whole += squares[e];
    s.hminus += (t.x[e + 1] - t.x[e]) * squares[e];
  }
  s.whole = error.scale * std::sqrt(s.whole);
  s.interior = error.scale * std::sqrt(s.interior);
  s.ends = error.scale * std::sqrt(s.ends);
  s.hminus = error.scale * std::sqrt(s.hminus);
  return s;
}
}  // namespace

InterfaceCurve l2_projection(const ContactInterface& gamma, const std::function<double(double)>& p,
                             const std::vector<double>& kinks) {
  const InterfaceTrace& t = gamma.nonmortar_trace;
  const std::vector<double> sorted_kinks = sorted(kinks);
  const auto& C = gamma.space.C;
  if (C.cols() != t.num_dofs())
    throw std::invalid_argument("l2_projection: M_h has " + std::to_string(C.cols()) + " trace nodes, the trace " +
                                std::to_string(t.num_dofs()));
  // the load (int p phi_j)_j, against the mass matrix of the trace's own degree
  Eigen::VectorXd load = Eigen::VectorXd::Zero(t.num_dofs());
  const int q = t.degree;
  for (int e = 0; e < t.num_elements(); ++e) {
    const double h = t.x[e + 1] - t.x[e];
    composite_rule(t.x[e], t.x[e + 1], CurveReader::points_inside(sorted_kinks, t.x[e], t.x[e + 1]), sorted_kinks,
                   [&](double x, double w) {
      const std::array<double, 3> phi = lagrange_1d(q, (x - t.x[e]) / h);
      for (int l = 0; l <= q; ++l) load[q * e + l] += w * phi[l] * p(x);
    });
  }
  const Eigen::SparseMatrix<double> M_phi = t.mass_matrix();
  // Gram matrix of the psi_i: (psi_i, psi_k) = (C M_phi C^T)_ik, SPD since the psi_i are independent
  const Eigen::SparseMatrix<double> gram = C * M_phi * C.transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(gram);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error("l2_projection: the Gram matrix of M_h (" + std::to_string(gram.rows()) +
                             " multipliers) could not be factored");
  const Eigen::VectorXd coefficients = factor.solve(Eigen::VectorXd(C * load));
  const Eigen::VectorXd nodal = C.transpose() * coefficients;
  return {t.node_positions(), std::vector<double>(nodal.data(), nodal.data() + nodal.size()), q};
}

PressureErrors pressure_errors(const ContactInterface& gamma, const InterfaceCurve& p_h,
                               const std::function<double(double)>& p, const std::vector<double>& kinks) {
  const InterfaceTrace& t = gamma.nonmortar_trace;
  check_curve(p_h, t);
  const std::vector<double> k = sorted(kinks);
  const SplitNorms computed = split_norms(t, element_squares(t, p_h, p, k));
  const SplitNorms best = split_norms(t, element_squares(t, l2_projection(gamma, p, k), p, k));
  const InterfaceCurve zero{t.x, std::vector<double>(t.x.size(), 0.0), 1};
  const SplitNorms size = split_norms(t, element_squares(t, zero, p, k));

  PressureErrors r;
  r.l2 = computed.whole;
  r.l2_interior = computed.interior;
  r.l2_ends = computed.ends;
  r.hminus = computed.hminus;
  r.best_l2 = best.whole;
  r.best_l2_interior = best.interior;
  r.best_hminus = best.hminus;
  r.norm_l2 = size.whole;
  r.norm_hminus = std::sqrt(t.length()) * size.whole;
  return r;
}

}  // namespace mortar
