// The two scenes of chapter 8 (README.md, "The scenes"). A scene gives, for the meshed bodies,
// the loads and Dirichlet data of each step of its load path, the initial gap g(x) and, for
// Tresca, the threshold s(x).
//  - manufactured: the exact Tresca solution of common/contact/manufactured_friction.hpp, u
//    prescribed on every outer side, one load step; s = F p;
//  - cattaneo: one material, the Hertz gap (x - L/2)^2 / (2R). Step 0 presses the top of body 1
//    down by delta (its x free); steps 1..N add a uniform shear traction Q / L on the top of
//    body 1, Q_k = (k / N) q_ratio F P with P the normal force of step 0 (Cattaneo-Mindlin:
//    normal load first, then the tangential one). The bottom of body 2 is clamped, the lateral
//    sides free. Body 1 is held in x by friction alone: with Q > F P nothing can hold it.
//  - cattaneo-exact: the same load path made exact, as chapter 5 made Hertz exact: each step k
//    prescribes the half-planes' Cattaneo-Mindlin field of Q_k = (k / N) q_ratio F P on every
//    outer side (common/contact/cattaneo_half_planes.hpp), with the half-width a = L sqrt(2) / 6
//    of chapter 5's hertz-exact scene (never a node), no body force and the Hertz gap: each
//    step's field is the exact solution of that step of the finite problem.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/contact/cattaneo_half_planes.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/contact/manufactured_friction.hpp"

namespace chapter08 {

struct SceneParameters {
  std::string name = "manufactured";
  double L = 1, R = 1, delta = 0.02;
  double friction = 0.3;
  double q_ratio = 0.6;  // Q / (F P) at the last step (cattaneo)
  int load_steps = 10;   // shear steps after the normal one (cattaneo)
  bool proportional = false;  // cattaneo: P and Q raised together from zero in load_steps steps
};

struct Scene {
  std::string name;
  std::function<double(double)> gap, threshold;
  int steps = 1;
  // Loads and Dirichlet data of step k on these bodies; normal_force is P of the normal step
  // (cattaneo's shear is a fraction of F P), unused by the manufactured scene.
  std::function<mortar::SceneData(const mortar::TwoBodies& bodies, int step, double normal_force)> step_data;
  // The first Newton step starts glued (every node closed and stuck): a body held only by
  // friction is free to slide in the first step of an open start.
  bool start_glued = false;
  // The supports of the physical limit's K (README.md, "Speed"): the scene's own, except that a
  // body held in x by friction alone is clamped there too (K alone must be definite).
  std::function<mortar::SceneData(const mortar::TwoBodies& bodies)> limit_data;
  // cattaneo-exact: the exact solution of each load step (empty for the other scenes)
  std::vector<std::shared_ptr<const mortar::CattaneoHalfPlanes>> exact_steps;
};

// The exact manufactured solution serves the manufactured scene; the others read only its two
// materials.
Scene make_scene(const SceneParameters& p, const mortar::ManufacturedFriction& exact);

// The half-width of cattaneo-exact's contact zone, L sqrt(2) / 6 (chapter 5's hertz-exact):
// irrational, so no mesh with nodes at rational multiples of L has a node on its edges.
double cattaneo_exact_half_width(double L);

// Cattaneo's loads: the top of body 1 at u_y = -delta with a shear traction Q / L along it,
// the bottom of body 2 clamped.
mortar::SceneData pressed_and_sheared(const mortar::TwoBodies& bodies, double delta, double Q, double L);

}  // namespace chapter08
