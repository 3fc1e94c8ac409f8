#include "p1_comparison.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace chapter07 {

mortar::BilateralStudy run_p1_study(const mortar::BilateralStudyOptions& p2_options,
                                    const mortar::ManufacturedContact& exact, mortar::Matching matching) {
  mortar::BilateralStudyOptions p1 = p2_options;
  p1.degree = 1;
  p1.n0 = 2 * p2_options.n0;  // P1 vertices = P2 nodes: the same unknowns level by level
  return mortar::run_bilateral_study(p1, exact, {matching, mortar::solve_bilateral, {}});
}

namespace {
// y at error e, log-log between the two levels whose errors bracket e (errors decrease).
double at_error(const std::vector<double>& error, const std::vector<double>& y, double e) {
  for (std::size_t k = 0; k + 1 < error.size(); ++k)
    if (error[k] >= e && e >= error[k + 1]) {
      const double t = std::log(e / error[k]) / std::log(error[k + 1] / error[k]);
      return std::exp(std::log(y[k]) + t * (std::log(y[k + 1]) - std::log(y[k])));
    }
  return std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

EqualError equal_error(const mortar::ConvergenceTable& p2, const mortar::ConvergenceTable& p1) {
  const std::vector<double> e1 = p1.column("err_energy"), e2 = p2.column("err_energy");
  const std::vector<double> d1 = p1.column("dofs"), d2 = p2.column("dofs");
  const std::vector<double> t1 = p1.column("time_s"), t2 = p2.column("time_s"), l1 = p1.column("limit_s");
  const double unit = l1.back();
  EqualError r;
  r.error = e1.back();
  r.p1_dofs = d1.back();
  r.p1_time = t1.back() / unit;
  r.p1_limit_ratio = t1.back() / l1.back();
  r.p2_dofs = at_error(e2, d2, r.error);
  r.p2_time = at_error(e2, t2, r.error) / unit;
  return r;
}

mortar::JsonObject equal_error_results(const EqualError& e) {
  mortar::JsonObject o;
  o.set("p1_err_energy", e.error)
      .set("p1_dofs", e.p1_dofs)
      .set("p2_dofs_same_error", e.p2_dofs)
      .set("dofs_ratio_p1_over_p2", e.p1_dofs / e.p2_dofs)
      .set("time_ratio_p1_over_p2", e.p1_time / e.p2_time);
  return o;
}

}  // namespace chapter07
