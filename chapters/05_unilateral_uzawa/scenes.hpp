// The scenes of chapter 5 (DESIGN.md conventions). Each gives the loads, the Dirichlet data
// and the initial gap g(x) >= 0 on Gamma_c; the constraint is [u.n] <= g.
//  - hertz: top of body 1 moved by (0, -delta), bottom of body 2 clamped, lateral sides free,
//    g = (x - L/2)^2 / (2R): a cylinder-like contact whose zone grows with delta;
//  - partial: the same supports, g = 2 delta x / L: the gap opens towards x = L, so the
//    bodies touch on the left part only and separate on the right;
//  - bilateral: chapter 4's exact solution, g = 0; the exact pressure is positive everywhere,
//    so the unilateral answer must be the bilateral one.
#pragma once

#include <functional>
#include <string>

#include "common/contact_scenes.hpp"
#include "common/manufactured_contact.hpp"

namespace chapter05 {

struct SceneParameters {
  std::string name = "hertz";
  double L = 1, R = 1, delta = 0.02;
};

struct UnilateralScene {
  mortar::SceneData data;
  std::function<double(double)> gap;
};

UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ManufacturedContact& exact);

}  // namespace chapter05
