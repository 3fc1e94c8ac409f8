#include "exercise.hpp"

namespace exercise {

Eigen::Vector2d patch_displacement(int l, const Eigen::Vector2d& p, const PatchData& d) {
  // sigma = diag(0, -p) in both bodies. Plane strain (eps_zz = 0):
  //   eps_xx = (1 + nu) ((1 - nu) sigma_xx - nu sigma_yy) / E = nu (1 + nu) p / E
  //   eps_yy = (1 + nu) ((1 - nu) sigma_yy - nu sigma_xx) / E = -(1 - nu^2) p / E
  const auto strains = [&](double E, double nu) {
    return Eigen::Vector2d(nu * (1 + nu) * d.pressure / E, -(1 - nu * nu) * d.pressure / E);
  };
  const Eigen::Vector2d e1 = strains(d.E1, d.nu1), e2 = strains(d.E2, d.nu2);
  const double uy_gamma = e2.y() * d.H2;  // body 2 squeezed from y = -H2 up to Gamma_c
  if (l == 1) return {e2.x() * p.x(), e2.y() * (p.y() + d.H2)};
  return {e1.x() * p.x(), uy_gamma + e1.y() * p.y()};
}

}  // namespace exercise
