#include "study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gsl/gsl_fit.h>

namespace chapter10 {

EnergyReference split_off_reference(LoopResult& run, double target) {
  const int n = static_cast<int>(run.steps.size());
  int stop = n - 1;  // the last reported step: the first below the target
  for (int k = 0; k < n; ++k)
    if (run.steps[k].rel_estimator <= target) {
      stop = k;
      break;
    }
  int first = stop + 1;
  if (n - first < 3) {
    first = std::max(0, n - 4);
    stop = first - 1;
  }
  if (stop < 2 || n - first < 3)
    throw std::runtime_error("the punch's reference needs 3 reported steps and 3 more past --target; " +
                             std::to_string(n) + " steps ran (raise --max-steps or --max-dofs)");
  std::vector<double> x, y;
  for (int k = first; k < n; ++k) {
    x.push_back(1.0 / run.steps[k].dofs);
    y.push_back(run.steps[k].strain_energy);
  }
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  const EnergyReference ref{c0, run.steps.back().strain_energy, n - first, run.steps[first].dofs, run.steps.back().dofs};
  run.steps.resize(stop + 1);
  return ref;
}

void measure_against_reference(LoopResult& run, const EnergyReference& ref) {
  for (StepRecord& r : run.steps) {
    r.rel_err_energy = std::sqrt(std::fabs(r.strain_energy - ref.W) / ref.W);
    r.err_energy = r.rel_err_energy * std::sqrt(2 * ref.W);
    r.effectivity = r.estimator / r.err_energy;
    r.rel_err_by_energy = r.rel_err_energy;
  }
}

mortar::ConvergenceTable step_table(const LoopResult& run) {
  mortar::ConvergenceTable table;
  for (const StepRecord& r : run.steps) {
    // the norm both columns are relative to: the exact one where known
    const double norm = r.err_energy / r.rel_err_energy;
    mortar::Row row{{"step", r.step},
                     {"h", r.h_mean},
                     {"dofs", r.dofs},
                     {"triangles_1", r.triangles[0]},
                     {"triangles_2", r.triangles[1]},
                     {"h_min", r.h_min},
                     {"min_angle_deg", r.min_angle_deg},
                     {"marked", r.marked},
                     {"newton_steps", r.newton_steps},
                     {"active_rows", r.active_rows},
                     {"err_energy", r.rel_err_energy},
                     {"err_energy_by_energy", r.rel_err_by_energy},
                     {"estimator", r.estimator / norm},
                     {"effectivity", r.effectivity}};
    const double total = r.estimator * r.estimator;
    for (int t = 0; t < mortar::estimator_terms; ++t)
      row.push_back({std::string("share_") + mortar::estimator_term_name(static_cast<mortar::EstimatorTerm>(t)),
                     total > 0 ? r.term2[t] / total : 0.0});
    row.insert(row.end(), {{"total_force", r.total_force},
                           {"solve_s", r.solve_s},
                           {"estimate_s", r.estimate_s},
                           {"refine_s", r.refine_s},
                           {"time_s", r.time_s}});
    table.add(row);
  }
  return table;
}

double rate_in_n(const LoopResult& run, const std::string& what) {
  std::vector<double> n, e;
  if (run.steps.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double smallest = run.steps.back().dofs / 16.0 * (1 - 1e-12);
  for (const StepRecord& r : run.steps)
    if (r.dofs >= smallest) {
      n.push_back(r.dofs);
      e.push_back(what == "estimator" ? r.estimator : r.err_energy);
    }
  return -mortar::log_log_slope(n, e);
}

double time_to_error(const LoopResult& run, double error) {
  for (const StepRecord& r : run.steps)
    if (r.rel_err_energy <= error) return r.time_s;
  return std::numeric_limits<double>::quiet_NaN();
}

int dofs_at_error(const LoopResult& run, double error) {
  for (const StepRecord& r : run.steps)
    if (r.rel_err_energy <= error) return r.dofs;
  return 0;
}

double pressure_exponent(const ContactStep& step, double x_corner, double r_min, double r_max) {
  std::vector<double> r, p;
  const mortar::InterfaceCurve& c = step.pressure;
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    const double d = std::fabs(c.x[k] - x_corner);
    if (d >= r_min && d <= r_max && c.value[k] > 0) {
      r.push_back(d);
      p.push_back(c.value[k]);
    }
  }
  return mortar::log_log_slope(r, p);
}

}  // namespace chapter10
