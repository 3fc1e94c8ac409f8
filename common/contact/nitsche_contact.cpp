#include "common/contact/nitsche_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "common/contact/nitsche_steps.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/fem/quadrature.hpp"
#include "common/interface/interface_trace.hpp"
#include "common/interface/merged_grid.hpp"

namespace mortar {

namespace {

using Local = Eigen::Matrix<double, 12, 1>;

// The side of body l on Gamma_c: the bottom of body 1, the top of body 2.
Side contact_side(int l) { return l == 0 ? Side::bottom : Side::top; }

// What one body contributes to a segment: its triangle's 6 dofs at local positions 6 l .. 6 l + 5,
// -sigma_yy of that triangle as a functional, and its trace's y-displacement at a and b.
void fill_body(const TwoBodies& bodies, int l, const InterfaceTrace& trace, int element, int triangle,
               double a, double b, double weight, NitscheSegment& s) {
  const Mesh& mesh = bodies.body(l).mesh;
  const auto& v = mesh.triangles[triangle];
  const Eigen::Matrix<double, 3, 6> CB = bodies.body(l).material.voigt() * strain_matrix(triangle_vertices(mesh, triangle));
  const double sign = l == 0 ? -1.0 : 1.0;  // [v.n] = v^2_y - v^1_y
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 2; ++c) {
      const int i = 6 * l + 2 * k + c;
      s.dofs[i] = bodies.dof(l, v[k], c);
      s.p(i) = -weight * CB(1, 2 * k + c);  // p^l = -sigma_yy
    }
  const double x0 = trace.x[element], x1 = trace.x[element + 1];
  for (int end = 0; end < 2; ++end) {
    const int node = trace.nodes[element + end];
    const int k = static_cast<int>(std::find(v.begin(), v.end(), node) - v.begin());
    const double phi_a = end == 0 ? (x1 - a) / (x1 - x0) : (a - x0) / (x1 - x0);
    const double phi_b = end == 0 ? (x1 - b) / (x1 - x0) : (b - x0) / (x1 - x0);
    s.jump_a(6 * l + 2 * k + 1) += sign * phi_a;
    s.jump_b(6 * l + 2 * k + 1) += sign * phi_b;
  }
}

// P_gamma on a segment: the traction part p(u) (0 for penalty) and the jump [u.n] at both ends.
struct SegmentState {
  double pu = 0, jump_a = 0, jump_b = 0;
};

SegmentState state_of(const NitscheSegment& s, const NitscheOptions& o, const Eigen::VectorXd& u) {
  Local ul;
  for (int i = 0; i < 12; ++i) ul(i) = u[s.dofs[i]];
  return {o.penalty ? 0.0 : s.p.dot(ul), s.jump_a.dot(ul), s.jump_b.dot(ul)};
}

double p_gamma(const NitscheSegment& s, const SegmentState& st, const std::function<double(double)>& gap, double x) {
  const double t = (x - s.a) / (s.b - s.a);
  return st.pu + s.gamma * ((1 - t) * st.jump_a + t * st.jump_b - gap(x));
}

// The segment cut at the roots of P_gamma (the quadratic through its values at a, the middle
// and b), as parameters 0 = s_0 < s_1 < ... = 1.
std::vector<double> cuts(double Pa, double Pm, double Pb) {
  const double c0 = Pa, c1 = -3 * Pa + 4 * Pm - Pb, c2 = 2 * Pa - 4 * Pm + 2 * Pb;
  std::vector<double> s = {0.0};
  std::vector<double> roots;
  const double scale = std::max({std::fabs(Pa), std::fabs(Pm), std::fabs(Pb)});
  if (std::fabs(c2) <= 1e-14 * scale) {
    if (std::fabs(c1) > 1e-14 * scale) roots.push_back(-c0 / c1);
  } else {
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc > 0) {
      // the stable pair of roots: q = -(c1 + sign(c1) sqrt(disc)) / 2, then q / c2 and c0 / q
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      roots.push_back(q / c2);
      if (q != 0) roots.push_back(c0 / q);
    }
  }
  std::sort(roots.begin(), roots.end());
  for (double r : roots)
    if (r > 1e-12 && r < 1 - 1e-12) s.push_back(r);
  s.push_back(1.0);
  return s;
}

// Each piece of a segment with whether P_gamma > 0 inside it.
struct Piece {
  double a, b;
  bool active;
};
std::vector<Piece> pieces(const NitscheSegment& s, const SegmentState& st, const std::function<double(double)>& gap) {
  const double m = 0.5 * (s.a + s.b);
  const double Pa = p_gamma(s, st, gap, s.a), Pm = p_gamma(s, st, gap, m), Pb = p_gamma(s, st, gap, s.b);
  const std::vector<double> c = cuts(Pa, Pm, Pb);
  std::vector<Piece> out;
  for (std::size_t k = 0; k + 1 < c.size(); ++k) {
    const double a = s.a + c[k] * (s.b - s.a), b = s.a + c[k + 1] * (s.b - s.a);
    out.push_back({a, b, p_gamma(s, st, gap, 0.5 * (a + b)) > 0});
  }
  return out;
}

}  // namespace

double harmonic_body1_weight(double E1, double h1, double E2, double h2) {
  return (h1 / E1) / (h1 / E1 + h2 / E2);
}

std::vector<NitscheSegment> nitsche_segments(const TwoBodies& bodies, const NitscheOptions& o) {
  const InterfaceTrace t1 = trace_on_side(bodies.body(0).mesh, contact_side(0));
  const InterfaceTrace t2 = trace_on_side(bodies.body(1).mesh, contact_side(1));
  const std::vector<int> tri1 = trace_triangles(bodies.body(0).mesh, t1);
  const std::vector<int> tri2 = trace_triangles(bodies.body(1).mesh, t2);
  for (const auto* tri : {&tri1, &tri2})
    if (std::count(tri->begin(), tri->end(), -1) > 0) throw std::logic_error("nitsche_segments: a trace edge belongs to no triangle");
  const MergedGrid grid = merge_traces(t1, t2);
  const double E1 = bodies.body(0).material.E(), E2 = bodies.body(1).material.E();
  std::vector<NitscheSegment> segments;
  segments.reserve(grid.segments.size());
  for (const MergedSegment& m : grid.segments) {
    NitscheSegment s;
    s.a = m.a;
    s.b = m.b;
    const double h1 = t1.x[m.element1 + 1] - t1.x[m.element1], h2 = t2.x[m.element2 + 1] - t2.x[m.element2];
    const double w = o.harmonic_weight ? harmonic_body1_weight(E1, h1, E2, h2) : o.body1_weight;
    fill_body(bodies, 0, t1, m.element1, tri1[m.element1], m.a, m.b, w, s);
    fill_body(bodies, 1, t2, m.element2, tri2[m.element2], m.a, m.b, 1 - w, s);
    s.gamma = o.fixed_gamma > 0 ? o.fixed_gamma : o.gamma0 * (w * E1 / h1 + (1 - w) * E2 / h2);
    segments.push_back(s);
  }
  return segments;
}

void add_nitsche_terms(const std::vector<NitscheSegment>& segments, const std::function<double(double)>& gap,
                       const NitscheOptions& o, const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                       std::vector<Eigen::Triplet<double>>* jacobian) {
  static const SegmentRule rule = gauss_legendre(3);  // P_gamma P_theta(v): degree 3 on each piece
  const double theta = o.penalty ? 0.0 : o.theta;
  for (const NitscheSegment& s : segments) {
    const SegmentState st = state_of(s, o, u);
    const Local p = o.penalty ? Local::Zero() : s.p;
    const double gamma = s.gamma, length = s.b - s.a;
    // - (theta / gamma) int p(u) p(v): p is constant on the segment
    Local r = -(theta / gamma) * length * st.pu * p;
    Eigen::Matrix<double, 12, 12> A = -(theta / gamma) * length * p * p.transpose();
    for (const Piece& piece : pieces(s, st, gap)) {
      if (!piece.active) continue;
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double x = piece.a + rule.points[q] * (piece.b - piece.a), W = rule.weights[q] * (piece.b - piece.a);
        const Local J = s.jump(x);
        const Local test = theta * p + gamma * J;  // P_theta(v)
        const Local trial = p + gamma * J;         // the derivative of P_gamma(u)
        r += (W / gamma) * std::max(0.0, p_gamma(s, st, gap, x)) * test;
        A += (W / gamma) * test * trial.transpose();
      }
    }
    for (int i = 0; i < 12; ++i) residual[s.dofs[i]] += r(i);
    if (jacobian != nullptr)
      for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) jacobian->emplace_back(s.dofs[i], s.dofs[j], A(i, j));
  }
}

double PressurePiece::at(double x) const {
  const double t = (x - a) / (b - a);
  return left * (1 - t) * (1 - 2 * t) + middle * 4 * t * (1 - t) + right * t * (2 * t - 1);
}

std::vector<PressurePiece> nitsche_pressure(const std::vector<NitscheSegment>& segments,
                                            const std::function<double(double)>& gap, const NitscheOptions& o,
                                            const Eigen::VectorXd& u) {
  std::vector<PressurePiece> out;
  for (const NitscheSegment& s : segments) {
    const SegmentState st = state_of(s, o, u);
    for (const Piece& piece : pieces(s, st, gap)) {
      PressurePiece pp{piece.a, piece.b, 0, 0, 0, piece.active};
      if (piece.active) {
        pp.left = std::max(0.0, p_gamma(s, st, gap, piece.a));
        pp.middle = std::max(0.0, p_gamma(s, st, gap, 0.5 * (piece.a + piece.b)));
        pp.right = std::max(0.0, p_gamma(s, st, gap, piece.b));
      }
      out.push_back(pp);
    }
  }
  return out;
}

double total_force(const std::vector<PressurePiece>& pressure) {
  double f = 0;
  for (const PressurePiece& p : pressure) f += (p.b - p.a) * (p.left + 4 * p.middle + p.right) / 6;  // Simpson
  return f;
}

double contact_half_width(const std::vector<PressurePiece>& pressure) {
  double length = 0;
  for (const PressurePiece& p : pressure)
    if (p.active) length += p.b - p.a;
  return length / 2;
}

std::pair<double, double> pressure_l2_error(const std::vector<PressurePiece>& pressure,
                                            const std::function<double(double)>& exact,
                                            const std::vector<double>& exact_kinks) {
  static const SegmentRule rule = gauss_legendre(8);
  double error = 0, norm = 0;
  for (const PressurePiece& p : pressure) {
    std::vector<double> cut = {p.a};
    for (double k : exact_kinks)
      if (k > p.a && k < p.b) cut.push_back(k);
    cut.push_back(p.b);
    for (std::size_t k = 0; k + 1 < cut.size(); ++k)
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double x = cut[k] + rule.points[q] * (cut[k + 1] - cut[k]), W = rule.weights[q] * (cut[k + 1] - cut[k]);
        const double e = exact(x), h = p.active ? p.at(x) : 0.0;
        error += W * (h - e) * (h - e);
        norm += W * e * e;
      }
  }
  return {std::sqrt(error), std::sqrt(norm)};
}

NitscheSolution solve_nitsche_contact(const TwoBodies& bodies, const SceneData& scene,
                                      const std::function<double(double)>& gap, const NitscheOptions& o,
                                      const Eigen::VectorXd* start) {
  const SparseMatrix K = bodies.stiffness();
  NitscheSolution sol;
  sol.segments = nitsche_segments(bodies, o);
  const std::vector<NitscheSegment>& segments = sol.segments;
  sol.u = start != nullptr ? *start : Eigen::VectorXd::Zero(bodies.num_dofs());
  if (sol.u.size() != bodies.num_dofs()) throw std::invalid_argument("solve_nitsche_contact: the start has the wrong size");
  for (std::size_t k = 0; k < scene.dirichlet.dofs.size(); ++k) sol.u[scene.dirichlet.dofs[k]] = scene.dirichlet.values[k];
  // K_ff and the numbering, once; the increments of the prescribed dofs are 0
  const ReducedSystem free = eliminate_dirichlet(K, scene.F, scene.dirichlet);
  std::vector<int> contact;
  for (const NitscheSegment& s : segments) contact.insert(contact.end(), s.dofs.begin(), s.dofs.end());
  const std::unique_ptr<NitscheStepSolver> steps =
      make_step_solver(o.linear_solver, free, contact, o.penalty || o.theta == 1);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int step = 1; step <= o.max_newton_steps; ++step) {
    Eigen::VectorXd R = K * sol.u - scene.F;
    triplets.clear();
    add_nitsche_terms(segments, gap, o, sol.u, R, &triplets);
    Eigen::VectorXd r(free.free_dofs.size());
    for (std::size_t k = 0; k < free.free_dofs.size(); ++k) r[k] = -R[free.free_dofs[k]];
    sol.newton_steps = step;
    Eigen::VectorXd du;
    try {
      du = steps->solve(triplets, r);
    } catch (const std::runtime_error& e) {
      // a singular Newton matrix (theta = 1 or a stiff body's traction far from coercive): the
      // run goes on with the last iterate, reported as not converged
      sol.failure = e.what();
      break;
    }
    sol.solver = steps->name();
    if (!du.allFinite()) {
      sol.failure = "the Newton step is not finite";
      break;
    }
    double u_max = 0;
    for (std::size_t k = 0; k < free.free_dofs.size(); ++k) {
      sol.u[free.free_dofs[k]] += du[k];
      u_max = std::max(u_max, std::fabs(sol.u[free.free_dofs[k]]));
    }
    if (du.lpNorm<Eigen::Infinity>() <= o.tol * std::max(u_max, 1e-300)) {
      sol.converged = true;
      break;
    }
  }
  sol.lu_fallbacks = steps->lu_fallbacks();
  if (o.keep_last_matrix) sol.last_matrix = free_block_plus(free, triplets);
  // the residual left, against the size of K u on the free dofs
  Eigen::VectorXd Ku = K * sol.u, R = Ku - scene.F;
  add_nitsche_terms(segments, gap, o, sol.u, R, nullptr);
  double r = 0, scale = 0;
  std::vector<bool> prescribed = scene.prescribed_mask(bodies.num_dofs());
  for (int i = 0; i < bodies.num_dofs(); ++i)
    if (!prescribed[i]) {
      r = std::max(r, std::fabs(R[i]));
      scale = std::max(scale, std::fabs(Ku[i]));
    }
  sol.residual = !sol.u.allFinite() || !std::isfinite(r) ? std::numeric_limits<double>::infinity() : scale > 0 ? r / scale : r;
  return sol;
}

}  // namespace mortar
