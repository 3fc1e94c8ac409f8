// The scenes of chapter 5 (README.md, "Notation"). Each gives the loads, the Dirichlet data
// and the initial gap g(x) >= 0 on Gamma_c; the constraint is [u.n] <= g.
//  - hertz: top of body 1 moved by (0, -delta), bottom of body 2 clamped, lateral sides free,
//    g = (x - L/2)^2 / (2R): a cylinder-like contact whose zone grows with delta;
//  - partial: the same supports, g = 2 delta x / L: the gap opens towards x = L, so the
//    bodies touch on the left part only and separate on the right;
//  - bilateral: chapter 4's exact solution, g = 0; the exact pressure is positive everywhere,
//    so the unilateral answer must be the bilateral one;
//  - signorini: an exact unilateral solution (common/contact/manufactured_contact.hpp): contact on
//    (0, x*), separation on (x*, L), x* = L (1/2 + sqrt(2)/10) never a node; u prescribed on
//    every outer side, g = A (x - x*)_+^2 / L. Theorem 5.1 is measured on it.
#pragma once

#include <functional>
#include <string>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/manufactured_contact.hpp"

namespace chapter05 {

struct SceneParameters {
  std::string name = "hertz";
  double L = 1, R = 1, delta = 0.02;
};

struct UnilateralScene {
  mortar::SceneData data;
  std::function<double(double)> gap;
};

// The exact solution a scene is measured against: the signorini profile for "signorini",
// chapter 4's sloped profile otherwise (used by the bilateral scene only).
mortar::ManufacturedContact make_exact(const SceneParameters& s, const mortar::Material& body1,
                                       const mortar::Material& body2);

UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ManufacturedContact& exact);

}  // namespace chapter05
