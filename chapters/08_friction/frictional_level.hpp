// One level of chapter 8: meshes, the dual basis on Gamma_c, the normal and the tangential rows,
// and the load path of the scene, each step one frictional contact problem solved by the
// semismooth Newton method (or by the fixed point on Tresca thresholds).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "common/contact/contact_fields.hpp"
#include "common/contact/friction_newton.hpp"
#include "common/linalg/physical_limit.hpp"
#include "scenes.hpp"

namespace chapter08 {

struct LevelSetup {
  mortar::TwoBodyGeometry geometry;
  int nonmortar = 0;  // body index
  mortar::FrictionLaw law = mortar::FrictionLaw::coulomb;
  double friction = 0.3;
  bool fixed_point = false;  // Coulomb as a sequence of Tresca problems
  double normal_force = 0;   // > 0: the P the scene's shear refers to (else step 0's)
  bool measure_limit = true;
  mortar::Repetitions repetitions{1, 5, 1.0};  // a level of seconds is timed once
  // Where the first Newton step starts: the status (and slip direction) at x, from a coarser
  // level (nested_start); empty: the scene's own start.
  std::function<std::pair<mortar::NodeStatus, double>(double x)> start_at;
};

// What one load step leaves: the solution, the curves on Gamma_c, the forces.
struct StepResult {
  mortar::FrictionSolution solution;
  Eigen::VectorXd u;  // both bodies, prescribed dofs included
  mortar::InterfaceCurve pressure, shear;  // the coefficients lambda_n, lambda_t at their nodes
  std::vector<mortar::NodeStatus> status;  // per node of the non-mortar trace (open at its ends)
  double normal_force = 0, shear_force = 0;  // int lambda_n,h and int lambda_t,h
  int newton_steps = 0, outer_iterations = 0;
  double time_s = 0;  // the load step's loads, Newton steps and reading, wall time
};

struct FrictionalLevel {
  mortar::TwoBodies bodies;
  mortar::ContactInterface gamma;
  mortar::Constraints normal, tangential;
  std::vector<StepResult> steps;
  double h1 = 0, h2 = 0;
  mortar::TimedLevel timing{};
  double time_s = 0, limit_s = 0;
  const StepResult& last() const { return steps.back(); }
  int newton_steps_max() const;
  int newton_steps_total() const;
  int lu_steps_total() const;
};

FrictionalLevel solve_frictional_level(const LevelSetup& setup, const Scene& scene, const mortar::Material& body1,
                                       const mortar::Material& body2);

// The stick zone read off the statuses, as ContactZone reads a contact zone: its outermost
// stick nodes and the midpoints to their neighbours (half_width() 0 when nothing sticks).
mortar::ContactZone stick_zone(const StepResult& step);

// The statuses of a coarser level's first load step, read at the nearest of its nodes, with the
// sign of its lambda_t: the next level then starts with its stick-slip point off by about one
// coarse element, instead of by the whole stick or slip zone.
std::function<std::pair<mortar::NodeStatus, double>(double x)> nested_start(const FrictionalLevel& coarser);

}  // namespace chapter08
