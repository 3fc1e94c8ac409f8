#include "common/contact/constraints.hpp"

#include <stdexcept>

#include "common/fem/lagrange_1d.hpp"
#include "common/fem/quadrature.hpp"
#include "common/interface/dual_basis.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

Matching parse_matching(const std::string& name) {
  if (name == "pointwise") return Matching::pointwise;
  if (name == "integral") return Matching::integral;
  throw std::invalid_argument("unknown matching '" + name + "' (pointwise or integral)");
}

std::string matching_name(Matching m) { return m == Matching::pointwise ? "pointwise" : "integral"; }

ContactInterface contact_traces(const TwoBodies& bodies, int nonmortar) {
  const ProfilePhase phase("interface and constraints");
  if (nonmortar != 0 && nonmortar != 1)
    throw std::invalid_argument("contact_traces: the non-mortar body is 0 or 1, got " +
                                std::to_string(nonmortar));
  ContactInterface g;
  g.nonmortar = nonmortar;
  // Gamma_c is the top side of body 2 and the bottom side of body 1.
  const auto side_of = [](int l) { return l == 0 ? Side::bottom : Side::top; };
  g.nonmortar_trace = trace_on_side(bodies.body(nonmortar).mesh, side_of(nonmortar));
  g.mortar_trace = trace_on_side(bodies.body(g.mortar()).mesh, side_of(g.mortar()));
  return g;
}

namespace {
ContactInterface interface_with(const TwoBodies& bodies, int nonmortar, double merge_tol, bool dual) {
  ContactInterface g = contact_traces(bodies, nonmortar);
  g.grid = merge_traces(g.nonmortar_trace, g.mortar_trace, merge_tol);
  g.space = dual ? dual_end_modified_p1(g.nonmortar_trace) : end_modified_space(g.nonmortar_trace);
  g.matrices = mortar_matrices(g.nonmortar_trace, g.mortar_trace, g.grid, g.space);
  return g;
}
}  // namespace

ContactInterface make_interface(const TwoBodies& bodies, int nonmortar, double merge_tol) {
  return interface_with(bodies, nonmortar, merge_tol, false);
}

ContactInterface make_dual_interface(const TwoBodies& bodies, int nonmortar) {
  return interface_with(bodies, nonmortar, 1e-12, true);
}

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

MatchingRows pointwise_matching_rows(const ContactInterface& g) {
  const ProfilePhase phase("interface and constraints");
  const int n = g.nonmortar_trace.num_dofs();
  std::vector<Eigen::Triplet<double>> nm, m;
  MatchingRows c;
  c.matching = Matching::pointwise;
  const auto& t = g.mortar_trace;
  for (int a = 0; a < n; ++a) {
    nm.emplace_back(a, a, 1.0);
    // value of the mortar trace at x_a: its q + 1 functions on the element containing x_a
    // (for P2 the non-mortar midpoints are matched too: every node of xi^1)
    const double x = g.nonmortar_trace.node_x(a);
    const int e = t.element_containing(x);
    const double s = (x - t.x[e]) / (t.x[e + 1] - t.x[e]);
    const std::array<double, 3> phi = lagrange_1d(t.degree, s);
    for (int k = 0; k <= t.degree; ++k) m.emplace_back(a, t.degree * e + k, phi[k]);
    c.row_node.push_back(a);
  }
  c.nonmortar.resize(n, n);
  c.mortar.resize(n, t.num_dofs());
  c.nonmortar.setFromTriplets(nm.begin(), nm.end());
  c.mortar.setFromTriplets(m.begin(), m.end());
  return c;
}

MatchingRows integral_matching_rows(const ContactInterface& g) {
  const ProfilePhase phase("interface and constraints");
  MatchingRows c{Matching::integral, g.matrices.D, g.matrices.M, {}};
  for (int i = 0; i < g.space.dim(); ++i) c.row_node.push_back(g.space.node_of(i));
  return c;
}

MatchingRows matching_rows(const ContactInterface& g, Matching matching) {
  return matching == Matching::pointwise ? pointwise_matching_rows(g) : integral_matching_rows(g);
}

Constraints build_constraints(const TwoBodies& bodies, const ContactInterface& g,
                              Matching matching, const std::vector<bool>& prescribed) {
  return constraint_rows(bodies, g, matching_rows(g, matching), prescribed);
}

namespace {
// The rows of c on the dofs of one component (0 = x, 1 = y) of both traces, the non-mortar
// coefficients times n_nm, the mortar ones times n_m; rows on prescribed dofs only dropped.
Constraints attach_rows(const TwoBodies& bodies, const ContactInterface& g, const MatchingRows& c,
                        const std::vector<bool>& prescribed, int component, double n_nm, double n_m) {
  const ProfilePhase phase("interface and constraints");
  if (static_cast<int>(prescribed.size()) != bodies.num_dofs())
    throw std::invalid_argument("constraint_rows: the prescribed mask has the wrong size");
  const int nm = g.nonmortar, m = g.mortar();

  Constraints out;
  out.matching = c.matching;
  std::vector<Eigen::Triplet<double>> entries;
  int kept = 0;
  for (int row = 0; row < c.nonmortar.rows(); ++row) {
    std::vector<Eigen::Triplet<double>> this_row;
    bool touches_unknown = false;
    auto add = [&](int dof, double value) {
      if (value == 0.0) return;
      this_row.emplace_back(kept, dof, value);
      touches_unknown = touches_unknown || !prescribed[dof];
    };
    for (RowMatrix::InnerIterator it(c.nonmortar, row); it; ++it)
      add(bodies.dof(nm, g.nonmortar_trace.nodes[it.col()], component), n_nm * it.value());
    for (RowMatrix::InnerIterator it(c.mortar, row); it; ++it)
      add(bodies.dof(m, g.mortar_trace.nodes[it.col()], component), n_m * it.value());
    if (!touches_unknown) continue;
    entries.insert(entries.end(), this_row.begin(), this_row.end());
    out.row_node.push_back(c.row_node[row]);
    out.row_source.push_back(row);
    out.pivot_dof.push_back(bodies.dof(nm, g.nonmortar_trace.nodes[c.row_node[row]], component));
    ++kept;
  }
  out.B.resize(kept, bodies.num_dofs());
  out.B.setFromTriplets(entries.begin(), entries.end());
  return out;
}
}  // namespace

Constraints constraint_rows(const TwoBodies& bodies, const ContactInterface& g, const MatchingRows& c,
                            const std::vector<bool>& prescribed) {
  return attach_rows(bodies, g, c, prescribed, 1, TwoBodies::normal_y(g.nonmortar), TwoBodies::normal_y(g.mortar()));
}

Constraints tangential_constraint_rows(const TwoBodies& bodies, const ContactInterface& g, const MatchingRows& c,
                                       const std::vector<bool>& prescribed) {
  // [u_t] = u^1_x - u^2_x: +1 on body 1's x dofs, -1 on body 2's, whichever side is non-mortar
  const double nm_sign = g.nonmortar == 0 ? 1.0 : -1.0;
  return attach_rows(bodies, g, c, prescribed, 0, nm_sign, -nm_sign);
}

Eigen::VectorXd tested_gap(const ContactInterface& gamma, const Constraints& c,
                           const std::function<double(double)>& g) {
  const ProfilePhase phase("interface and constraints");
  const InterfaceTrace& t = gamma.nonmortar_trace;
  Eigen::VectorXd G(static_cast<Eigen::Index>(c.row_source.size()));
  if (c.matching == Matching::pointwise) {
    for (std::size_t r = 0; r < c.row_source.size(); ++r) G[r] = g(t.node_x(c.row_source[r]));
    return G;
  }
  const Eigen::VectorXd g_psi = integrals_against_basis(gamma.space, t, g);
  for (std::size_t r = 0; r < c.row_source.size(); ++r) G[r] = g_psi[c.row_source[r]];
  return G;
}

}  // namespace mortar
