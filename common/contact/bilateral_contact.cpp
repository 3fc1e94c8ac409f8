#include "common/contact/bilateral_contact.hpp"

#include "common/linalg/physical_limit.hpp"
#include "common/study/stopwatch.hpp"

namespace mortar {

BilateralSolution solve_bilateral(const TwoBodies& bodies, const SceneData& scene,
                                  const BilateralOptions& options) {
  BilateralSolution s;
  const Stopwatch clock;
  const SparseMatrix K = bodies.stiffness();
  s.gamma = make_interface(bodies, options.nonmortar);
  s.constraints = build_constraints(bodies, s.gamma, options.matching,
                                    scene.prescribed_mask(bodies.num_dofs()));
  const ReducedSystem system = eliminate_dirichlet(K, scene.F, scene.dirichlet);
  const SaddlePointProblem problem = reduce_to_free_dofs(
      system, s.constraints, Eigen::VectorXd::Zero(s.constraints.B.rows()));
  const SaddlePointSolution x = solve_saddle_point(problem, options.solver, options.backend);
  s.u = system.expand(x.u);
  s.lambda = x.lambda;
  s.time_s = clock.seconds();
  return s;
}

double two_body_limit(const TwoBodies& bodies, const SceneData& scene) {
  return measure_physical_limit([&] {
    const SparseMatrix K = bodies.stiffness();
    return eliminate_dirichlet(K, Eigen::VectorXd::Zero(K.rows()), scene.dirichlet).K;
  });
}

}  // namespace mortar
