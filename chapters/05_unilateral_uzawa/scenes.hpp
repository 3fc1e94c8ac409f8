// The scenes of chapter 5 (README.md, "Notation"). Each gives the loads, the Dirichlet data
// and the initial gap g(x) >= 0 on Gamma_c; the constraint is [u.n] <= g.
//  - hertz: top of body 1 moved by (0, -delta), bottom of body 2 clamped, lateral sides free,
//    g = (x - L/2)^2 / (2R): a cylinder-like contact whose zone grows with delta;
//  - partial: the same supports, g = 2 delta x / L: the gap opens towards x = L, so the
//    bodies touch on the left part only and separate on the right;
//  - bilateral: chapter 4's exact solution, g = 0; the exact pressure is positive everywhere,
//    so the unilateral answer must be the bilateral one;
//  - signorini: a smooth closure (common/contact/manufactured_contact.hpp): pressure on (0, x*),
//    none on (x*, L), x* = L (1/2 + sqrt(2)/10) never a node; u prescribed on every outer side,
//    g = A (x - x*)_+^2 / L. Its jump [u.n] is zero everywhere, so the same field also solves
//    the glued problem: bilateral in disguise;
//  - hertz-exact: each body a piece of an elastic half-plane under the Hertz pressure
//    (common/contact/hertz_half_planes.hpp), half-width a = L sqrt(2) / 6 (never a node),
//    centre L/2, u prescribed on every outer side, no body force, g = (x - L/2)^2 / (2R): an
//    exact solution with true contact edges. Theorem 5.1 is measured on it.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/exact_contact.hpp"

namespace chapter05 {

struct SceneParameters {
  std::string name = "hertz";
  double L = 1, R = 1, delta = 0.02;
};

struct UnilateralScene {
  mortar::SceneData data;
  std::function<double(double)> gap;
};

// The exact solution a scene is measured against: the half-planes for "hertz-exact", the
// signorini profile for "signorini", chapter 4's sloped profile otherwise (used by the
// bilateral scene only; the others read just the two materials from it).
std::unique_ptr<const mortar::ExactContact> make_exact(const SceneParameters& s, const mortar::Material& body1,
                                                       const mortar::Material& body2);
// The half-width of the hertz-exact scene's contact zone, L sqrt(2) / 6: irrational, so no
// mesh with nodes at rational multiples of L has a node on an edge of the zone.
double hertz_exact_half_width(double L);

UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ExactContact& exact);

}  // namespace chapter05
