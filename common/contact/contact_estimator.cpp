#include "common/contact/contact_estimator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/contact/contact_fields.hpp"
#include "common/fem/quadrature.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

const char* estimator_term_name(EstimatorTerm t) {
  switch (t) {
    case EstimatorTerm::volume: return "volume";
    case EstimatorTerm::jump: return "jump";
    case EstimatorTerm::neumann: return "neumann";
    case EstimatorTerm::contact_normal: return "contact_normal";
    case EstimatorTerm::contact_tangential: return "contact_tangential";
    case EstimatorTerm::penetration: return "penetration";
    case EstimatorTerm::complementarity: return "complementarity";
  }
  return "?";
}

double ContactEstimate::total() const {
  double sum = 0;
  for (double t : term2) sum += t;
  return std::sqrt(sum);
}

double ContactEstimate::term(EstimatorTerm t) const { return std::sqrt(term2[static_cast<int>(t)]); }

double combined_modulus(const Material& m1, const Material& m2) {
  return 1 / ((1 - m1.nu() * m1.nu()) / m1.E() + (1 - m2.nu() * m2.nu()) / m2.E());
}

namespace {

// Every contribution goes to one triangle of one body and to one term, so that the indicators
// and the shares add up to the same total.
struct Sink {
  ContactEstimate& e;
  void add(int l, int t, EstimatorTerm term, double value) {
    e.indicator2[l][t] += value;
    e.term2[static_cast<int>(term)] += value;
  }
};

// The edges of a triangle mesh: each with its one or two triangles. Sorting the 3 N_T
// (node pair, triangle) records is the only step above O(N), and a cheap one.
struct MeshEdge {
  int a, b;          // end nodes
  int t0, t1 = -1;   // neighbours; t1 = -1 on the boundary
};
std::vector<MeshEdge> mesh_edges(const Mesh& mesh) {
  struct Record {
    int a, b, t;
  };
  std::vector<Record> r;
  r.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int p = mesh.triangles[t][k], q = mesh.triangles[t][(k + 1) % 3];
      r.push_back({std::min(p, q), std::max(p, q), t});
    }
  std::sort(r.begin(), r.end(), [](const Record& x, const Record& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  std::vector<MeshEdge> edges;
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (!edges.empty() && edges.back().a == r[k].a && edges.back().b == r[k].b)
      edges.back().t1 = r[k].t;
    else
      edges.push_back({r[k].a, r[k].b, r[k].t});
  }
  return edges;
}

Eigen::Matrix2d stress_matrix(const Eigen::Vector3d& s) {
  Eigen::Matrix2d m;
  m << s[0], s[2], s[2], s[1];
  return m;
}

Eigen::Vector2d outward_normal(Side side) {
  switch (side) {
    case Side::bottom: return {0, -1};
    case Side::right: return {1, 0};
    case Side::top: return {0, 1};
    case Side::left: return {-1, 0};
  }
  return {0, 0};
}

Side contact_side(int l) { return l == 0 ? Side::bottom : Side::top; }

// The side a boundary edge lies on: the one both end nodes belong to (-1: none).
int common_side(const std::vector<unsigned>& sides_of_node, int a, int b) {
  const unsigned both = sides_of_node[a] & sides_of_node[b];
  for (int s = 0; s < 4; ++s)
    if (both & (1u << s)) return s;
  return -1;
}

// Volume: h_T^2 / E ||f + div sigma_h||_T^2, div sigma_h = 0 on P1 (the interior residual of Hild
// and Nicaise's estimator, squared and divided by E so that eta has the energy norm's units).
void volume_terms(const Mesh& mesh, double E, const VectorField& f, int l, Sink& sink) {
  if (!f) return;
  const TriangleRule rule = triangle_rule(4);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const double h = std::max({(x[1] - x[0]).norm(), (x[2] - x[1]).norm(), (x[0] - x[2]).norm()});
    double integral = 0;
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const Eigen::Vector2d p = x[0] + rule.points[q][0] * (x[1] - x[0]) + rule.points[q][1] * (x[2] - x[0]);
      integral += rule.weights[q] * f(p).squaredNorm();
    }
    sink.add(l, t, EstimatorTerm::volume, h * h / E * mesh.area(t) * integral);
  }
}

// Interior edges: h_E / E ||[sigma_h n]||_E^2, the jump constant on the edge, half
// to each neighbour. Traction sides: h_E / E ||g_N - sigma_h n||_E^2 (the Neumann residual).
void edge_terms(const Mesh& mesh, const std::vector<MeshEdge>& edges, const std::vector<Eigen::Vector3d>& stress,
                double E, const std::vector<std::pair<Side, VectorField>>& neumann, int l, Sink& sink) {
  std::vector<unsigned> sides_of_node(mesh.nodes.size(), 0);
  for (int s = 0; s < 4; ++s)
    for (int a : mesh.side_nodes[s]) sides_of_node[a] |= 1u << s;
  const SegmentRule rule = gauss_legendre(4);
  for (const MeshEdge& edge : edges) {
    const Eigen::Vector2d pa = mesh.nodes[edge.a], pb = mesh.nodes[edge.b];
    const double h = (pb - pa).norm();
    if (edge.t1 >= 0) {
      const Eigen::Vector2d n(pb.y() - pa.y(), pa.x() - pb.x());  // either normal: the jump is squared
      const Eigen::Vector2d jump = (stress_matrix(stress[edge.t0]) - stress_matrix(stress[edge.t1])) * n / h;
      const double value = h / E * h * jump.squaredNorm();
      sink.add(l, edge.t0, EstimatorTerm::jump, value / 2);
      sink.add(l, edge.t1, EstimatorTerm::jump, value / 2);
      continue;
    }
    const int side = common_side(sides_of_node, edge.a, edge.b);
    if (side < 0 || static_cast<Side>(side) == contact_side(l)) continue;  // Gamma_c: contact_terms
    for (const auto& [s, g] : neumann) {
      if (static_cast<int>(s) != side) continue;
      const Eigen::Vector2d sn = stress_matrix(stress[edge.t0]) * outward_normal(s);
      double integral = 0;
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const Eigen::Vector2d p = pa + rule.points[q] * (pb - pa);
        integral += rule.weights[q] * ((g ? g(p) : Eigen::Vector2d::Zero()) - sn).squaredNorm();
      }
      sink.add(l, edge.t0, EstimatorTerm::neumann, h / E * h * integral);
    }
  }
}

// The breakpoints of both traces, merged: on each piece between them lambda_h (broken linear on
// the non-mortar trace) and both traces are single polynomials.
std::vector<double> all_breakpoints(const ContactInterface& gamma) {
  std::vector<double> x = gamma.nonmortar_trace.x;
  x.insert(x.end(), gamma.mortar_trace.x.begin(), gamma.mortar_trace.x.end());
  std::sort(x.begin(), x.end());
  const double tol = 1e-12 * (x.back() - x.front());
  std::vector<double> merged;
  for (double v : x)
    if (merged.empty() || v - merged.back() > tol) merged.push_back(v);
  return merged;
}

// lambda_h at x on the piece around `mid`, 0 off the non-mortar trace (a free edge there).
double multiplier_at(const BrokenCurve& lambda_h, const InterfaceTrace& nm, double mid, double x) {
  if (mid < nm.x.front() || mid > nm.x.back()) return 0.0;
  const int e = nm.element_containing(mid);
  return lambda_h(e, (x - nm.x[e]) / (nm.x[e + 1] - nm.x[e]));
}

// Calls piece(a, b) for the pieces of [x0, x1] cut at the breakpoints inside it.
template <class Piece>
void for_pieces(const std::vector<double>& breaks, double x0, double x1, Piece piece) {
  double a = x0;
  auto it = std::upper_bound(breaks.begin(), breaks.end(), x0 + 1e-12 * (x1 - x0));
  for (; it != breaks.end() && *it < x1 - 1e-12 * (x1 - x0); ++it) {
    piece(a, *it);
    a = *it;
  }
  piece(a, x1);
}

// Gamma_c, both bodies: h_E / E ||sigma_h n.n + lambda_h||_E^2 and h_E / E ||sigma_h n.t||_E^2
// (Hild-Nicaise's contact terms, with their lambda_h the multiplier of the discrete problem).
// lambda_h is the pressure (>= 0) and sigma_N = -p on both sides, so the exact pair gives 0.
// lambda_h is the traction the discrete equations put on both bodies (Wohlmuth 2007: the
// Neumann datum on Gamma_c), so the residual compares sigma_h n with the same function on each.
void contact_terms(const std::vector<int>& edge_triangle, const InterfaceTrace& trace,
                   const std::vector<Eigen::Vector3d>& stress, double E, const ContactInterface& gamma,
                   const BrokenCurve& lambda_h, const std::vector<double>& breaks, int l, Sink& sink) {
  const SegmentRule rule = gauss_legendre(3);  // (constant + linear)^2: exact
  for (int e = 0; e < trace.num_elements(); ++e) {
    const int t = edge_triangle[e];
    const double x0 = trace.x[e], x1 = trace.x[e + 1], h = x1 - x0;
    const double s_nn = stress[t][1], s_nt = stress[t][2];  // n = (0, -+1): n.sigma n = sigma_yy
    double normal = 0;
    for_pieces(breaks, x0, x1, [&](double a, double b) {
      const double mid = 0.5 * (a + b);
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double x = a + rule.points[q] * (b - a);
        const double r = s_nn + multiplier_at(lambda_h, gamma.nonmortar_trace, mid, x);
        normal += rule.weights[q] * (b - a) * r * r;
      }
    });
    sink.add(l, t, EstimatorTerm::contact_normal, h / E * normal);
    sink.add(l, t, EstimatorTerm::contact_tangential, h / E * h * s_nt * s_nt);
  }
}

// The normal displacement u_y of a body at its trace nodes.
std::vector<double> trace_uy(const TwoBodies& bodies, int l, const InterfaceTrace& trace, const Eigen::VectorXd& u) {
  std::vector<double> v;
  for (int node : trace.nodes) v.push_back(u[bodies.dof(l, node, 1)]);
  return v;
}

// Non-mortar edges: the constraint and complementarity, pointwise.
//  - penetration E* / h_E ||([u_h.n] - g)^+||_E^2. The integral constraints int psi_i ([u_h.n]
//    - g) <= 0 only bound means, so u_h may leave the convex set pointwise. The distance of u_h
//    to it in the energy norm is the energy of closing ([u_h.n] - g)^+, of order E* |.|_{H^{1/2}}^2
//    (the two half-planes in series: E*). Hild and Nicaise's discrete solution never penetrates
//    (nodal constraints on P1 traces: no such term is needed there); Wohlmuth's estimator keeps a
//    nonconformity term of this kind. For a function that varies on the scale of an element,
//    |.|_{H^{1/2}}^2 ~ ||.||_{L2}^2 / h: the L2 norm with weight E*/h_E, computable element by
//    element (a deviation from the global H^{1/2} norm, for locality).
//  - complementarity int_E lambda_h^+ (g - [u_h.n])^+: Hild and Nicaise's term int -lambda_h
//    u_hn (there both factors have a sign) made sign-safe for the dual basis, whose lambda_h
//    takes negative values, and for a u_h that penetrates; it is a work, with the energy's units
//    without a modulus.
// Bilateral: the penetration term takes |[u_h.n] - g| (both signs violate) and there is no
// complementarity.
void constraint_terms(const TwoBodies& bodies, const Eigen::VectorXd& u, const ContactInterface& gamma,
                      const std::vector<int>& edge_triangle, const BrokenCurve& lambda_h,
                      const std::vector<double>& breaks, const EstimatorData& data, Sink& sink) {
  const InterfaceTrace &nm = gamma.nonmortar_trace, &m = gamma.mortar_trace;
  const std::vector<double> u_nm = trace_uy(bodies, gamma.nonmortar, nm, u), u_m = trace_uy(bodies, gamma.mortar(), m, u);
  const double sign = gamma.nonmortar == 0 ? 1.0 : -1.0;  // [u.n] = u2_y - u1_y = sign (u_m - u_nm)
  const double e_star = combined_modulus(bodies.body(0).material, bodies.body(1).material);
  // g - [u_h.n] has kinks where the sign changes and g is any smooth function: 4 sub-pieces of
  // 4 Gauss points each, no more than a constant amount of work per piece
  const SegmentRule rule = gauss_legendre(4);
  constexpr int sub = 4;
  for (int e = 0; e < nm.num_elements(); ++e) {
    const double x0 = nm.x[e], x1 = nm.x[e + 1], h = x1 - x0;
    double penetration = 0, complementarity = 0;
    for_pieces(breaks, x0, x1, [&](double a, double b) {
      const double mid = 0.5 * (a + b);
      if (mid < m.x.front() || mid > m.x.back()) return;  // no mortar side: no jump defined
      for (int k = 0; k < sub; ++k)
        for (std::size_t q = 0; q < rule.points.size(); ++q) {
          const double x = a + (k + rule.points[q]) / sub * (b - a), w = rule.weights[q] * (b - a) / sub;
          const double jump = sign * (m.evaluate(u_m, x) - nm.evaluate(u_nm, x));
          const double d = jump - (data.gap ? data.gap(x) : 0.0);
          if (!data.unilateral) {
            penetration += w * d * d;
            continue;
          }
          penetration += w * std::pow(std::max(d, 0.0), 2);
          complementarity += w * std::max(multiplier_at(lambda_h, nm, mid, x), 0.0) * std::max(-d, 0.0);
        }
    });
    const int t = edge_triangle[e];
    sink.add(gamma.nonmortar, t, EstimatorTerm::penetration, e_star / h * penetration);
    if (data.unilateral) sink.add(gamma.nonmortar, t, EstimatorTerm::complementarity, complementarity);
  }
}

}  // namespace

ContactEstimate estimate_contact_error(const TwoBodies& bodies, const Eigen::VectorXd& u,
                                       const ContactInterface& gamma, const Constraints& c,
                                       const Eigen::VectorXd& lambda, const EstimatorData& data) {
  const ProfilePhase phase("error estimator");
  for (int l = 0; l < 2; ++l)
    if (bodies.body(l).mesh.degree() != 1)
      throw std::invalid_argument("estimate_contact_error: P1 meshes only (body " + std::to_string(l + 1) + " is P2)");
  if (c.matching != Matching::integral)
    throw std::invalid_argument("estimate_contact_error: needs integral matching (lambda_h = sum_i lambda_i psi_i)");
  if (u.size() != bodies.num_dofs() || lambda.size() != c.B.rows())
    throw std::invalid_argument("estimate_contact_error: u or lambda of the wrong size");

  ContactEstimate estimate;
  Sink sink{estimate};
  const BrokenCurve lambda_h = multiplier_function(gamma, c, lambda);
  const std::vector<double> breaks = all_breakpoints(gamma);
  std::array<std::vector<int>, 2> edge_triangle;
  for (int l = 0; l < 2; ++l) {
    const Body& body = bodies.body(l);
    const double E = body.material.E();
    estimate.indicator2[l].assign(body.mesh.triangles.size(), 0.0);
    const std::vector<MeshEdge> edges = mesh_edges(body.mesh);
    const std::vector<Eigen::Vector3d> stress = element_stresses(body.mesh, body.material, bodies.part(u, l));
    const InterfaceTrace& trace = l == gamma.nonmortar ? gamma.nonmortar_trace : gamma.mortar_trace;
    edge_triangle[l] = trace_triangles(body.mesh, trace);
    if (std::count(edge_triangle[l].begin(), edge_triangle[l].end(), -1) > 0)
      throw std::invalid_argument("estimate_contact_error: a trace edge is no boundary edge of its body");
    volume_terms(body.mesh, E, data.body_force[l], l, sink);
    edge_terms(body.mesh, edges, stress, E, data.neumann[l], l, sink);
    contact_terms(edge_triangle[l], trace, stress, E, gamma, lambda_h, breaks, l, sink);
  }
  constraint_terms(bodies, u, gamma, edge_triangle[gamma.nonmortar], lambda_h, breaks, data, sink);
  return estimate;
}

}  // namespace mortar
