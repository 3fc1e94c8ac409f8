#include "contact_step.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/contact/dual_condensation.hpp"
#include "common/contact/saddle_point.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/interface/mortar_matrices.hpp"
#include "common/timing/stopwatch.hpp"

namespace chapter10 {

namespace {
// The nodes of a trace inside [a, b]; both ends must be nodes.
void cut_trace(mortar::InterfaceTrace& t, double a, double b) {
  const double tol = 1e-12 * (t.x.back() - t.x.front());
  mortar::InterfaceTrace cut;
  cut.degree = t.degree;
  for (int k = 0; k < t.num_nodes(); ++k)
    if (t.x[k] >= a - tol && t.x[k] <= b + tol) {
      cut.x.push_back(t.x[k]);
      cut.nodes.push_back(t.nodes[k]);
    }
  if (cut.x.size() < 3 || std::fabs(cut.x.front() - a) > tol || std::fabs(cut.x.back() - b) > tol)
    throw std::invalid_argument("the contact line [" + std::to_string(a) + ", " + std::to_string(b) +
                                "] does not end at nodes of both bodies");
  t = std::move(cut);
}

// lambda~ at x: the previous multipliers, linear between their nodes, zero outside them.
double previous_pressure(const mortar::InterfaceCurve& p, double x) {
  if (p.x.size() < 2 || x < p.x.front() || x > p.x.back()) return 0.0;
  const auto it = std::upper_bound(p.x.begin(), p.x.end(), x);
  const std::size_t k = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - p.x.begin(), 1), p.x.size() - 1);
  const double s = (x - p.x[k - 1]) / (p.x[k] - p.x[k - 1]);
  return (1 - s) * p.value[k - 1] + s * p.value[k];
}

// The first active set from the previous solution (see the header).
std::vector<bool> predicted_active(const ContactStep& r, const mortar::SaddlePointProblem& reduced,
                                   const mortar::ReducedSystem& system, const mortar::CondensedContact& condensed,
                                   const NestedStart& start) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(condensed.rows());
  if (start.u.size() == r.bodies.num_dofs()) {
    Eigen::VectorXd u_free(system.free_dofs.size());
    for (std::size_t k = 0; k < system.free_dofs.size(); ++k) u_free[k] = start.u[system.free_dofs[k]];
    w = reduced.B * u_free - reduced.G;
  }
  std::vector<bool> active(condensed.rows());
  for (int i = 0; i < condensed.rows(); ++i) {
    const double x = r.gamma.nonmortar_trace.x[r.constraints.row_node[i]];
    const double c = condensed.A.coeff(condensed.pivots[i], condensed.pivots[i]);
    active[i] = previous_pressure(start.pressure, x) + c * w[i] > 0;
  }
  return active;
}
}  // namespace

mortar::ContactInterface overlap_dual_interface(const mortar::TwoBodies& bodies, int nonmortar) {
  mortar::ContactInterface g = mortar::contact_traces(bodies, nonmortar);
  const double a = std::max(g.nonmortar_trace.x.front(), g.mortar_trace.x.front());
  const double b = std::min(g.nonmortar_trace.x.back(), g.mortar_trace.x.back());
  cut_trace(g.nonmortar_trace, a, b);
  cut_trace(g.mortar_trace, a, b);
  g.grid = mortar::merge_traces(g.nonmortar_trace, g.mortar_trace);
  g.space = mortar::dual_end_modified_p1(g.nonmortar_trace);
  g.matrices = mortar::mortar_matrices(g.nonmortar_trace, g.mortar_trace, g.grid, g.space);
  return g;
}

ContactStep solve_contact_step(const Scene& scene, mortar::Mesh mesh1, mortar::Mesh mesh2, int nonmortar,
                               const NestedStart* start) {
  const mortar::Stopwatch clock;
  ContactStep r{mortar::TwoBodies({std::move(mesh1), scene.material(0)}, {std::move(mesh2), scene.material(1)}),
                {}, {}, {}, {}, {}, 0, 0, 0};
  // 1. Loads and Dirichlet data on the meshes as they are; K of both bodies.
  const mortar::SceneData data = scene.data(r.bodies);
  mortar::SparseMatrix K = r.bodies.stiffness();
  // 2. Gamma_c from the traces of today's meshes: merged grid, dual basis, D and M.
  r.gamma = overlap_dual_interface(r.bodies, nonmortar);
  // 3. The rows int psi_i [u_h.n] <= int psi_i g (the weighted gap), as in chapter 6.
  r.constraints = mortar::constraint_rows(r.bodies, r.gamma, mortar::integral_matching_rows(r.gamma),
                                          data.prescribed_mask(r.bodies.num_dofs()));
  const Eigen::VectorXd G = mortar::tested_gap(r.gamma, r.constraints, [&scene](double x) { return scene.gap(x); });
  // 4. Dirichlet elimination and the condensation of the non-mortar normal dofs.
  const mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, data.F, data.dirichlet);
  mortar::SparseMatrix().swap(K);
  const mortar::SaddlePointProblem reduced = mortar::reduce_to_free_dofs(system, r.constraints, G);
  mortar::CondensedContact condensed = mortar::condense_contact(reduced);
  // 5. The semismooth Newton method, started from the previous step's solution.
  mortar::DualContactOptions options;
  options.unilateral = scene.unilateral();
  if (start != nullptr && options.unilateral)
    options.initial_active = predicted_active(r, reduced, system, condensed, *start);
  const mortar::DualContactSolution x = mortar::solve_dual_contact(condensed, options);
  r.u = system.expand(x.u);
  r.lambda = x.lambda;
  r.newton_steps = x.iterations;
  r.active_rows = static_cast<int>(std::count(x.active.begin(), x.active.end(), true));
  r.solve_s = clock.seconds();
  r.pressure = mortar::contact_pressure(r.gamma, r.constraints, r.lambda);
  return r;
}

NestedStart nested_start(const ContactStep& step, Eigen::VectorXd u_prolonged) {
  return {step.pressure, std::move(u_prolonged)};
}

double strain_energy(const ContactStep& step) {
  // element by element, 1/2 |T| eps^T C eps: no second assembly of K
  double W = 0;
  for (int l = 0; l < 2; ++l) {
    const mortar::Body& body = step.bodies.body(l);
    const Eigen::VectorXd u = step.bodies.part(step.u, l);
    const Eigen::Matrix3d C = body.material.voigt();
    for (int t = 0; t < static_cast<int>(body.mesh.triangles.size()); ++t) {
      Eigen::Matrix<double, 6, 1> ue;
      for (int k = 0; k < 3; ++k) ue.segment<2>(2 * k) = u.segment<2>(2 * body.mesh.triangles[t][k]);
      const Eigen::Vector3d eps = mortar::strain_matrix(mortar::triangle_vertices(body.mesh, t)) * ue;
      W += 0.5 * body.mesh.area(t) * eps.dot(C * eps);
    }
  }
  return W;
}

}  // namespace chapter10
