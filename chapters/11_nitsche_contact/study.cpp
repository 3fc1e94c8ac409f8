#include "study.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "common/contact/bilateral_contact.hpp"
#include "mortar_reference.hpp"

namespace chapter11 {

const std::vector<std::string>& method_names() {
  static const std::vector<std::string> names = {"nitsche", "penalty", "penalty_fixed", "mortar", "dual"};
  return names;
}

void solve_level(const Options& o, const Scene& scene, Level& level, const Level* coarser) {
  level.methods.clear();
  const bool nested = coarser != nullptr && o.start == "nested";
  for (std::size_t k = 0; k < method_names().size(); ++k) {
    const std::string& m = method_names()[k];
    if (m == "mortar" || m == "dual") level.methods.push_back(run_mortar(level, scene, o.nonmortar, m == "dual"));
    else
      level.methods.push_back(run_without_multipliers(level, scene, m, method_options(o, m), nested ? coarser : nullptr,
                                                      nested ? &coarser->methods[k] : nullptr));
    const MethodResult& r = level.methods.back();
    std::printf("level %d  %-13s energy %.4e  L2 %.4e  pressure %.4e  |a_h - a| %.3e m  steps %2d%s  %.3f s\n",
                level.index, m.c_str(), r.err_energy, r.err_l2, r.err_pressure, r.half_width_error_m, r.newton_steps,
                r.converged ? "" : " (no convergence)", r.time_s);
    if (r.krylov_counted) std::printf("         Krylov iterations of the last matrix: %d\n", r.krylov_iterations);
    if (r.lu_fallbacks > 0)
      std::printf("         %d symmetric Newton steps were not positive definite (solved by LU)\n", r.lu_fallbacks);
    if (!r.failure.empty()) std::printf("         Newton stopped: %s\n", r.failure.c_str());
  }
  level.limit_s = mortar::two_body_limit(level.bodies, level.data);
}

mortar::Row level_row(const Level& level) {
  mortar::Row row = {{"h", level.h},
                     {"h1", level.h1},
                     {"h2", level.h2},
                     {"dofs", static_cast<double>(level.bodies.num_dofs())},
                     {"time_s", level.methods.front().time_s},
                     {"limit_s", level.limit_s}};
  for (const MethodResult& r : level.methods) {
    row.push_back({"err_energy_" + r.name, r.err_energy});
    row.push_back({"err_l2_" + r.name, r.err_l2});
    row.push_back({"err_pressure_" + r.name, r.err_pressure});
    row.push_back({"half_width_error_m_" + r.name, r.half_width_error_m});
    row.push_back({"newton_steps_" + r.name, static_cast<double>(r.newton_steps)});
    // blank where not counted, -1 where the Krylov method did not converge
    row.push_back({"krylov_iterations_" + r.name, r.krylov_counted ? r.krylov_iterations : std::nan("")});
    row.push_back({"time_s_" + r.name, r.time_s});
  }
  return row;
}

std::vector<SweepPoint> gamma_sweep(const Options& o, const Scene& scene, const Level& level) {
  std::vector<SweepPoint> points;
  for (int k = -9; k <= 9; ++k) {
    const double gamma0 = std::pow(10.0, k / 3.0);
    for (double theta : {1.0, 0.0, -1.0, 2.0}) {  // 2.0 marks penalty
      Options variant = o;
      variant.theta = theta > 1 ? 1 : theta;
      variant.gamma0 = variant.penalty_gamma0 = gamma0;
      const bool penalty = theta > 1;
      const mortar::NitscheOptions n = method_options(variant, penalty ? "penalty" : "nitsche");
      SweepPoint p{theta, gamma0, run_without_multipliers(level, scene, penalty ? "penalty" : "nitsche", n)};
      std::printf("sweep: %-8s gamma0 %.3g  energy %.4e  pressure %.4e  steps %2d%s\n",
                  penalty ? "penalty" : ("theta " + std::to_string(static_cast<int>(theta))).c_str(), gamma0,
                  p.result.err_energy, p.result.err_pressure, p.result.newton_steps,
                  p.result.converged ? "" : " (no convergence)");
      points.push_back(std::move(p));
    }
  }
  return points;
}

void write_sweep(const std::string& path, const std::vector<SweepPoint>& points) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << "method,theta,gamma0,err_energy,err_l2,err_pressure,half_width_error_m,newton_steps,converged,solver,"
       "krylov_iterations\n";
  for (const SweepPoint& p : points) {
    const bool penalty = p.theta > 1;
    f << (penalty ? "penalty" : "nitsche") << "," << (penalty ? std::string("") : std::to_string(p.theta)) << ","
      << p.gamma0 << "," << p.result.err_energy << "," << p.result.err_l2 << "," << p.result.err_pressure << ","
      << p.result.half_width_error_m << "," << p.result.newton_steps << "," << (p.result.converged ? 1 : 0) << ","
      << p.result.solver << "," << p.result.krylov_iterations << "\n";
  }
}

std::vector<StiffnessPoint> stiffness_sweep(const Options& o) {
  std::vector<StiffnessPoint> points;
  for (int k = -6; k <= 6; k += 2) {
    Options variant = o;
    variant.E1 = std::pow(10.0, k) * o.E2;
    const int softer = variant.E1 < variant.E2 ? 1 : variant.E1 > variant.E2 ? 2 : o.nonmortar;
    const Scene scene = make_scene(variant);
    const Level level = make_level(variant, scene, o.sweep_level);
    for (const std::string traction : {"body1", "body2", "harmonic", "mortar", "dual"}) {
      StiffnessPoint p{variant.E1 / variant.E2, traction, {}};
      if (traction == "mortar" || traction == "dual") {
        p.result = run_mortar(level, scene, softer, traction == "dual");
        p.traction = "-";
        p.result.name = traction;
      } else {
        variant.traction = traction;
        p.result = run_without_multipliers(level, scene, "nitsche", method_options(variant, "nitsche"));
      }
      std::printf("stiffness: E1/E2 %.0e  %-8s %-8s energy %.4e  pressure %.4e  steps %2d%s\n", p.ratio,
                  p.result.name.c_str(), p.traction.c_str(), p.result.err_energy, p.result.err_pressure,
                  p.result.newton_steps, p.result.converged ? "" : " (no convergence)");
      points.push_back(std::move(p));
    }
  }
  return points;
}

void write_stiffness_sweep(const std::string& path, const std::vector<StiffnessPoint>& points) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << "E1_over_E2,method,traction,err_energy,err_l2,err_pressure,half_width_error_m,newton_steps,converged\n";
  for (const StiffnessPoint& p : points)
    f << p.ratio << "," << p.result.name << "," << p.traction << "," << p.result.err_energy << "," << p.result.err_l2
      << "," << p.result.err_pressure << "," << p.result.half_width_error_m << "," << p.result.newton_steps << ","
      << (p.result.converged ? 1 : 0) << "\n";
}

}  // namespace chapter11
