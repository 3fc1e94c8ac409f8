#include "common/contact/bilateral_contact.hpp"

#include <utility>

#include "common/linalg/physical_limit.hpp"
#include "common/study/stopwatch.hpp"

namespace mortar {

BilateralSolution solve_bilateral(const TwoBodies& bodies, const SceneData& scene,
                                  const BilateralOptions& options) {
  BilateralSolution s;
  const Stopwatch clock;
  s.gamma = make_interface(bodies, options.nonmortar);
  s.constraints = build_constraints(bodies, s.gamma, options.matching,
                                    scene.prescribed_mask(bodies.num_dofs()));
  SaddlePointSolution x = solve_glued_bodies(bodies, scene, s.constraints, options.solver, options.backend);
  s.u = std::move(x.u);
  s.lambda = std::move(x.lambda);
  s.time_s = clock.seconds();
  return s;
}

SaddlePointSolution solve_glued_bodies(const TwoBodies& bodies, const SceneData& scene,
                                       const Constraints& constraints, SaddleSolver solver,
                                       SpdBackend backend) {
  const SparseMatrix K = bodies.stiffness();
  const ReducedSystem system = eliminate_dirichlet(K, scene.F, scene.dirichlet);
  const SaddlePointProblem problem = reduce_to_free_dofs(
      system, constraints, Eigen::VectorXd::Zero(constraints.B.rows()));
  SaddlePointSolution x = solve_saddle_point(problem, solver, backend);
  x.u = system.expand(x.u);
  return x;
}

double two_body_limit(const TwoBodies& bodies, const SceneData& scene) {
  return measure_physical_limit([&] {
    const SparseMatrix K = bodies.stiffness();
    return eliminate_dirichlet(K, Eigen::VectorXd::Zero(K.rows()), scene.dirichlet).K;
  });
}

}  // namespace mortar
