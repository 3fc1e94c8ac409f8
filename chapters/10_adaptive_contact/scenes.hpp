// The scenes of chapter 10. Each one says where the two bodies are (the rectangles of the
// first meshes), what holds them (loads, Dirichlet data, free sides), the initial gap g on
// Gamma_c, and, where it is known, the exact solution the estimator is checked against.
//  - hertz-exact: chapter 5's exact Hertz solution (two elastic half-planes under the Hertz
//    pressure, common/contact/hertz_half_planes.hpp) with a contact zone small beside the
//    bodies: half-width a = L sqrt(2) / 29 (0.0488 L, never a node), centre L/2, the exact
//    displacement prescribed on every outer side, no body force;
//  - bilateral: chapter 4's manufactured solution (glued in the normal direction, free to
//    slide), exact tractions on the lateral sides, a body force: the estimator's volume and
//    Neumann terms at work, and a smooth solution where adaptivity should refine almost
//    uniformly;
//  - punch: body 1 a square block of width w = L/4 centred on body 2, (L/2 - w/2, L/2 + w/2) x
//    (0, w), ten times stiffer (E1 = 10, E2 = 1 unless given), its top pushed down by delta onto
//    body 2 = (0, L) x (-H2, 0), whose bottom rests on rollers; every other side free, g = 0.
//    The contact zone ends at body 1's corners, where the pressure is singular like r^(lambda-1)
//    (wedge_exponent.hpp): no closed form.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "common/contact/contact_estimator.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/contact/exact_contact.hpp"
#include "common/fem/mesh.hpp"
#include "common/study/bilateral_study.hpp"

namespace chapter10 {

struct SceneOptions {
  std::string name = "hertz-exact";
  // the course's two bodies (E1 = 1, nu1 = 0.3, E2 = 3, nu2 = 0.25, L = 1, H1 = H2 = 0.5), here
  // with h2 / h1 = 4/3 on the first mesh; their nonmortar is ignored (LoopOptions says it)
  mortar::TwoBodyOptions bodies = [] {
    mortar::TwoBodyOptions b;
    b.h_ratio = 4.0 / 3;
    return b;
  }();
  double R = 1;          // hertz-exact: the gap's radius, p0 = a E* / (2R)
  double delta = 0.01;   // punch: the downward displacement of body 1's top [m]
  int n0 = 10;           // body 1's elements along its contact side on the first mesh
};

// The hertz-exact scene's half-width, L sqrt(2) / 29: irrational, so no mesh node lies on an
// edge of the zone, and below L/20 (the zone is small beside the bodies).
double small_zone_half_width(double L);

class Scene {
 public:
  explicit Scene(const SceneOptions& o);
  const SceneOptions& options() const { return o_; }
  bool unilateral() const { return o_.name != "bilateral"; }
  // The rectangle and cells of body l's first mesh; its cells are (nearly) square, which keeps
  // newest-vertex bisection on isosceles right triangles.
  mortar::RectangleSpec first_mesh(int l, int refinements = 0) const;
  mortar::Material material(int l) const;
  // null for the punch
  const mortar::ExactContact* exact() const { return exact_.get(); }
  mortar::SceneData data(const mortar::TwoBodies& bodies) const;
  double gap(double x) const;
  mortar::EstimatorData estimator_data() const;

 private:
  SceneOptions o_;
  std::unique_ptr<const mortar::ExactContact> exact_;
};

}  // namespace chapter10
