#include "common/contact/contact_fields.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/fem/lagrange_1d.hpp"
#include "common/fem/quadrature.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

double InterfaceCurve::at(int piece, double s) const {
  const std::array<double, 3> phi = lagrange_1d(degree, s);
  double v = 0;
  for (int l = 0; l <= degree; ++l) v += phi[l] * value[degree * piece + l];
  return v;
}

Eigen::VectorXd multiplier_coefficients(const ContactInterface& g, const Constraints& c,
                                        const Eigen::VectorXd& lambda) {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(g.space.dim());
  for (std::size_t r = 0; r < c.row_source.size(); ++r) full[c.row_source[r]] = lambda[r];
  return full;
}

BrokenCurve multiplier_function(const ContactInterface& g, const Constraints& c, const Eigen::VectorXd& lambda) {
  return multiplier_function(g.space, g.nonmortar_trace, multiplier_coefficients(g, c, lambda));
}

InterfaceCurve contact_pressure(const ContactInterface& g, const Constraints& c,
                                const Eigen::VectorXd& lambda) {
  const ProfilePhase phase("post-processing");
  const InterfaceTrace& t = g.nonmortar_trace;
  InterfaceCurve p{t.node_positions(), std::vector<double>(static_cast<std::size_t>(t.num_dofs()), 0.0), t.degree};
  if (c.matching == Matching::integral) {
    // lambda_h = sum_i lambda_i psi_i = sum_j (C^T lambda)_j phi_j
    const Eigen::VectorXd nodal = g.space.C.transpose() * multiplier_coefficients(g, c, lambda);
    for (int j = 0; j < t.num_dofs(); ++j) p.value[j] = nodal[j];
  } else {
    const std::vector<double> weight = t.node_integrals();
    for (std::size_t r = 0; r < c.row_source.size(); ++r) {
      const int a = c.row_source[r];
      p.value[a] = lambda[r] / weight[a];
    }
  }
  return p;
}

InterfaceCurve normal_jump(const TwoBodies& bodies, const ContactInterface& g,
                           const Eigen::VectorXd& u) {
  const ProfilePhase phase("post-processing");
  // nodal normal displacement u_y of each trace, then both evaluated at the breakpoints
  auto uy = [&](int l, const InterfaceTrace& t) {
    std::vector<double> v;
    for (int node : t.nodes) v.push_back(u[bodies.dof(l, node, 1)]);
    return v;
  };
  const std::vector<double> nm = uy(g.nonmortar, g.nonmortar_trace), m = uy(g.mortar(), g.mortar_trace);
  InterfaceCurve jump;
  jump.degree = std::max(g.nonmortar_trace.degree, g.mortar_trace.degree);
  const auto add = [&](double x) {
    const double u_nm = g.nonmortar_trace.evaluate(nm, x), u_m = g.mortar_trace.evaluate(m, x);
    // [u.n] = u1.n1 + u2.n2 = u2_y - u1_y whichever side is the non-mortar one
    const double u1 = g.nonmortar == 0 ? u_nm : u_m, u2 = g.nonmortar == 0 ? u_m : u_nm;
    jump.x.push_back(x);
    jump.value.push_back(u2 - u1);
  };
  const std::vector<double>& b = g.grid.breakpoints;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (k > 0 && jump.degree == 2) add(0.5 * (b[k - 1] + b[k]));
    add(b[k]);
  }
  return jump;
}

double total_contact_force(const ContactInterface& g, const Constraints& c,
                           const Eigen::VectorXd& lambda) {
  const ProfilePhase phase("post-processing");
  if (c.matching == Matching::pointwise) return lambda.sum();
  const Eigen::VectorXd psi_integral =
      integrals_against_basis(g.space, g.nonmortar_trace, [](double) { return 1.0; });
  double total = 0;
  for (std::size_t r = 0; r < c.row_source.size(); ++r) total += lambda[r] * psi_integral[c.row_source[r]];
  return total;
}

// The integrand is squared, and a pressure scales with E: at E = 1e300 its square overflows,
// at E = 1e-160 it underflows. So the differences are divided by the largest of them before
// squaring and the root multiplied back (a scaled sum of squares), which leaves the result
// the same for every unit of E.
double l2_error(const InterfaceCurve& curve, const std::function<double(double)>& exact) {
  const SegmentRule g = gauss_legendre(4);
  std::vector<double> difference, weight;
  for (int e = 0; e < curve.pieces(); ++e) {
    const double a = curve.x[curve.degree * e], b = curve.x[curve.degree * (e + 1)];
    for (std::size_t q = 0; q < g.points.size(); ++q) {
      const double s = g.points[q];
      const double value = curve.at(e, s);
      difference.push_back(value - exact(a + s * (b - a)));
      weight.push_back(g.weights[q] * (b - a));
    }
  }
  double scale = 0;
  for (double d : difference) {
    if (std::isnan(d)) return d;  // passed on, not hidden
    scale = std::max(scale, std::fabs(d));
  }
  if (scale == 0 || std::isinf(scale)) return scale;
  double sum = 0;
  for (std::size_t k = 0; k < difference.size(); ++k) sum += weight[k] * std::pow(difference[k] / scale, 2);
  return scale * std::sqrt(sum);
}

double l2_norm(const InterfaceCurve& curve, const std::function<double(double)>& f) {
  InterfaceCurve zero{curve.x, std::vector<double>(curve.x.size(), 0.0), curve.degree};
  return l2_error(zero, f);
}

double ContactZone::half_width() const {
  if (empty) return 0.0;
  return 0.5 * (0.5 * (right_active + right_inactive) - 0.5 * (left_active + left_inactive));
}

ContactZone contact_zone(const InterfaceCurve& p) {
  ContactZone z;
  const int n = static_cast<int>(p.x.size());
  int first = -1, last = -1;
  for (int i = 0; i < n; ++i)
    if (p.value[i] > 0) {
      if (first < 0) first = i;
      last = i;
      ++z.active_nodes;
      if (i > 0 && p.value[i - 1] > 0) ++z.active_elements;
    }
  if (first < 0) return z;
  z.empty = false;
  z.left_active = p.x[first];
  z.right_active = p.x[last];
  // at the ends of Gamma_c the zone can reach no further
  z.left_inactive = first > 0 ? p.x[first - 1] : p.x[first];
  z.right_inactive = last + 1 < n ? p.x[last + 1] : p.x[last];
  return z;
}

double relative_l2_difference(const InterfaceCurve& a, const InterfaceCurve& b) {
  if (a.x.size() != b.x.size()) throw std::invalid_argument("relative_l2_difference: the curves have different points");
  // values divided by the largest before squaring: any unit of stress, up to 1e300 Pa
  double scale = 0;
  for (std::size_t k = 0; k < b.x.size(); ++k) scale = std::max({scale, std::fabs(a.value[k]), std::fabs(b.value[k])});
  if (!(scale > 0)) return 0.0;
  double difference = 0, norm = 0;
  for (std::size_t e = 0; e + 1 < b.x.size(); ++e) {
    const double h = b.x[e + 1] - b.x[e];
    const double d0 = (a.value[e] - b.value[e]) / scale, d1 = (a.value[e + 1] - b.value[e + 1]) / scale;
    const double b0 = b.value[e] / scale, b1 = b.value[e + 1] / scale;
    difference += h / 3 * (d0 * d0 + d0 * d1 + d1 * d1);
    norm += h / 3 * (b0 * b0 + b0 * b1 + b1 * b1);
  }
  return norm > 0 ? std::sqrt(difference / norm) : 0.0;
}

}  // namespace mortar
