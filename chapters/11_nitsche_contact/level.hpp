// One level of chapter 11: the exact Hertz scene on one pair of meshes, solved by every method,
// each measured against the exact solution the same way.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/hertz_half_planes.hpp"
#include "common/contact/nitsche_contact.hpp"
#include "options.hpp"

namespace chapter11 {

// Chapter 5's hertz-exact scene: half-width a = L sqrt(2) / 6 (never a node), centre L / 2,
// the half-planes' displacement on every outer side, g = (x - L/2)^2 / (2R).
struct Scene {
  std::unique_ptr<const mortar::HertzHalfPlanes> exact;
  std::function<double(double)> gap;
};
Scene make_scene(const Options& o);

struct MethodResult {
  std::string name;
  double err_energy = 0, err_l2 = 0, err_pressure = 0;
  double half_width_error_m = 0, total_force = 0;
  int newton_steps = 0;
  bool converged = true;
  double residual = 0;  // Nitsche and penalty: max |R| / max |K u| on the free dofs at the end
  int lu_fallbacks = 0;  // Nitsche and penalty: symmetric steps that were not positive definite
  std::string failure;   // why Newton stopped early, or empty
  bool krylov_counted = false;  // (Level::count_krylov)
  int krylov_iterations = 0;    // of the last linear system (krylov.hpp; -1: did not converge); mortar: K's
  std::string solver;
  double time_s = 0;
  std::vector<double> pressure_samples;  // at Level::sample_x
  Eigen::VectorXd u;  // both bodies (the next level's nested start)
};

struct Level {
  int index = 0;
  bool count_krylov = true;  // count the Krylov iterations of each method's last matrix
  mortar::TwoBodyGeometry geometry;
  mortar::TwoBodies bodies;
  mortar::SceneData data;
  double h = 0, h1 = 0, h2 = 0, limit_s = 0;
  std::vector<double> sample_x;  // where pressures are sampled for the figure
  // the gap every method reads: the scene's g, or (--gap interpolated) its linear interpolant
  // on the level's merged grid, which a P1 jump can follow exactly
  std::function<double(double)> gap;
  std::vector<MethodResult> methods;
};

// The meshes and the scene's data of one level (n1 = n0 2^level, square cells).
Level make_level(const Options& o, const Scene& scene, int index);

// The options of one contact-without-multipliers method: "nitsche" (--theta, --gamma0,
// --traction), "penalty" (gamma = penalty_gamma0 E / h), "penalty_fixed" (gamma frozen at the
// coarsest level's value).
mortar::NitscheOptions method_options(const Options& o, const std::string& method);

// Solves the level by Nitsche or penalty and measures the result; `coarser` (the same method
// on the level below) gives the start, interpolated, or none: u = 0 inside.
MethodResult run_without_multipliers(const Level& level, const Scene& scene, const std::string& name,
                                     const mortar::NitscheOptions& options, const Level* coarser = nullptr,
                                     const MethodResult* coarse_result = nullptr);

// ||u - u_h|| in energy and L2 over both bodies, relative to ||u||.
std::pair<double, double> displacement_errors(const Level& level, const Scene& scene, const Eigen::VectorXd& u);

}  // namespace chapter11
