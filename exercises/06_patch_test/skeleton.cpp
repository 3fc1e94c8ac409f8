#include "exercise.hpp"

namespace exercise {

Eigen::Vector2d patch_displacement(int l, const Eigen::Vector2d& p, const PatchData& d) {
  // Your code here: the stress is the same everywhere; find the plane-strain strains of each
  // body, then the linear displacement that satisfies the rollers and is continuous in y.
  (void)l;
  (void)p;
  (void)d;
  return Eigen::Vector2d::Zero();
}

}  // namespace exercise
