// Step 6 of chapter 9: chapter 6's answer on the same level, on rank 0 alone: the condensation
// and the semismooth Newton method with one CHOLMOD factorization per step
// (common/contact/dual_condensation.hpp), and the physical limit of the level (one assembly,
// factorization and solve of K, common/linalg/physical_limit.hpp). The distributed answer must
// equal the first; its time is reported against the second.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/contact/two_bodies.hpp"

namespace chapter09 {

struct CholmodAnswer {
  Eigen::VectorXd u, lambda;
  std::vector<bool> active;
  int steps = 0;
  double time_s = 0;   // the whole contact solve: condensation and every Newton step
  double limit_s = 0;  // the physical limit of the level
};

// The physical limit of the level alone (for sizes where chapter 6's answer takes too long), the
// better of two measurements.
double physical_limit(const mortar::TwoBodies& bodies, const mortar::SceneData& scene);

// `unilateral`: contact (Hertz); otherwise bilateral, w = 0 at every node (manufactured).
CholmodAnswer cholmod_answer(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                             const mortar::Constraints& constraints, const Eigen::VectorXd& G, bool unilateral);

}  // namespace chapter09
