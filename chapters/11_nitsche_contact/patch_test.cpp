#include "patch_test.hpp"

#include <algorithm>
#include <cmath>

#include "common/contact/contact_scenes.hpp"

namespace chapter11 {

PatchResult nitsche_patch_test(const Options& o, const mortar::NitscheOptions& method) {
  mortar::TwoBodyGeometry g;
  g.L = o.L;
  g.H1 = o.H1;
  g.H2 = o.H2;
  g.n1 = 6;  // h2 / h1 = 3 / 7: the traces share only the ends and x = L / 2
  g.n2 = 14;
  g.m1 = 3;
  g.m2 = 7;
  g.jitter = o.jitter;
  const mortar::TwoBodies bodies =
      mortar::make_two_bodies(g, mortar::Material(o.E1, o.nu1), mortar::Material(o.E2, o.nu2));
  const double p = 0.01 * std::min(o.E1, o.E2);
  const mortar::SceneData scene = mortar::patch_test_scene(bodies, p);
  // Body 1 is held in y by the contact alone: Newton starts with the bodies overlapping by
  // 1% of H1, so that P_gamma > 0 on all of Gamma_c and the first matrix is not singular.
  Eigen::VectorXd start = Eigen::VectorXd::Zero(bodies.num_dofs());
  for (int a = 0; a < bodies.body(0).mesh.num_nodes(); ++a) start[bodies.dof(0, a, 1)] = -0.01 * o.H1;
  const auto no_gap = [](double) { return 0.0; };
  // Penalty transmits p through a penetration p / gamma: uniform, and the stress exact, only for a
  // gamma uniform along Gamma_c; with --jitter the elements differ, so it takes the value of the
  // unjittered h1 = L / 6 everywhere
  mortar::NitscheOptions run = method;
  if (run.penalty && run.fixed_gamma == 0) run.fixed_gamma = run.gamma0 * o.E1 / (o.L / g.n1);
  const mortar::NitscheSolution s = mortar::solve_nitsche_contact(bodies, scene, no_gap, run, &start);
  PatchResult r;
  r.newton_steps = s.newton_steps;
  for (int l = 0; l < 2; ++l) {
    const auto stress = mortar::element_stresses(bodies.body(l).mesh, bodies.body(l).material, bodies.part(s.u, l));
    for (const Eigen::Vector3d& sigma : stress) r.rel_error = std::max(r.rel_error, std::fabs(sigma[1] + p) / p);
  }
  if (!s.converged) r.rel_error = std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace chapter11
