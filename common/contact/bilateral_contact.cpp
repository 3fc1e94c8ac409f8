#include "common/contact/bilateral_contact.hpp"

#include "common/linalg/physical_limit.hpp"

namespace mortar {

void solve_saddle_point(const ReducedSystem& system, const BilateralOptions& options, BilateralSolution& s) {
  const Eigen::VectorXd no_gap = Eigen::VectorXd::Zero(s.constraints.B.rows());
  SaddlePointSolution x = solve_saddle_point(reduce_to_free_dofs(system, s.constraints, no_gap),
                                             options.solver, options.backend);
  s.u = system.expand(x.u);
  s.lambda = std::move(x.lambda);
}

BilateralSolution solve_bilateral(const TwoBodies& bodies, const SceneData& scene,
                                  const BilateralOptions& options) {
  BilateralSolution s;
  s.gamma = make_interface(bodies, options.nonmortar);
  s.constraints = build_constraints(bodies, s.gamma, options.matching, scene.prescribed_mask(bodies.num_dofs()));
  solve_saddle_point(eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet), options, s);
  s.pressure = contact_pressure(s.gamma, s.constraints, s.lambda);
  s.jump = normal_jump(bodies, s.gamma, s.u);
  return s;
}

SparseMatrix two_body_limit_matrix(const TwoBodies& bodies, const SceneData& scene) {
  const SparseMatrix K = bodies.stiffness();
  return eliminate_dirichlet(K, Eigen::VectorXd::Zero(K.rows()), scene.dirichlet).K;
}

double two_body_limit(const TwoBodies& bodies, const SceneData& scene) {
  return measure_physical_limit([&] { return two_body_limit_matrix(bodies, scene); });
}

}  // namespace mortar
