#include <algorithm>
#include <cmath>

#include "exercise.hpp"

namespace exercise {

namespace {
// index e of the element [x_e, x_{e+1}] that contains the point
int element_of(const std::vector<double>& x, double point) {
  const int e = static_cast<int>(std::upper_bound(x.begin(), x.end(), point) - x.begin()) - 1;
  return std::clamp(e, 0, static_cast<int>(x.size()) - 2);
}
}  // namespace

Eigen::MatrixXd mixed_mass(const std::vector<double>& x1, const std::vector<double>& x2) {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(x1.size()),
                                            static_cast<Eigen::Index>(x2.size()));
  // where both grids are: the products vanish elsewhere, one factor being undefined there
  const double lo = std::max(x1.front(), x2.front()), hi = std::min(x1.back(), x2.back());
  if (!(hi > lo)) return P;
  // the breakpoints of both grids inside [lo, hi], and its ends
  std::vector<double> breaks = {lo, hi};
  for (const auto* x : {&x1, &x2})
    for (double p : *x)
      if (p > lo && p < hi) breaks.push_back(p);
  std::sort(breaks.begin(), breaks.end());
  const double g = 0.5 / std::sqrt(3.0);  // 2-point Gauss on [0, 1]: 1/2 -+ g, weights 1/2
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1];
    if (b - a <= 1e-12 * (hi - lo)) continue;  // a merged pair: no segment
    const int e1 = element_of(x1, 0.5 * (a + b)), e2 = element_of(x2, 0.5 * (a + b));
    for (double t : {0.5 - g, 0.5 + g}) {
      const double x = a + t * (b - a), w = 0.5 * (b - a);
      const double s1 = (x - x1[e1]) / (x1[e1 + 1] - x1[e1]), s2 = (x - x2[e2]) / (x2[e2 + 1] - x2[e2]);
      const double phi1[2] = {1 - s1, s1}, phi2[2] = {1 - s2, s2};
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) P(e1 + j, e2 + k) += w * phi1[j] * phi2[k];
    }
  }
  return P;
}

}  // namespace exercise
