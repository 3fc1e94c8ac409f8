#include "scenes.hpp"

#include <stdexcept>

namespace chapter05 {

namespace {
// Top of body 1 moved by (0, -delta), bottom of body 2 clamped; no load.
mortar::SceneData pressed_between_plates(const mortar::TwoBodies& bodies, double delta) {
  mortar::SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  const auto add = [&](int l, mortar::Side side, const Eigen::Vector2d& value) {
    for (int a : bodies.body(l).mesh.nodes_on(side))
      for (int c = 0; c < 2; ++c) {
        scene.dirichlet.dofs.push_back(bodies.dof(l, a, c));
        scene.dirichlet.values.push_back(value[c]);
      }
  };
  add(0, mortar::Side::top, Eigen::Vector2d(0, -delta));
  add(1, mortar::Side::bottom, Eigen::Vector2d(0, 0));
  return scene;
}
}  // namespace

UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ManufacturedContact& exact) {
  UnilateralScene u;
  if (s.name == "hertz") {
    u.data = pressed_between_plates(bodies, s.delta);
    const double x0 = s.L / 2, R = s.R;
    u.gap = [x0, R](double x) { return (x - x0) * (x - x0) / (2 * R); };
  } else if (s.name == "partial") {
    u.data = pressed_between_plates(bodies, s.delta);
    const double slope = 2 * s.delta / s.L;
    u.gap = [slope](double x) { return slope * x; };
  } else if (s.name == "bilateral") {
    u.data = mortar::manufactured_scene(bodies, exact);
    u.gap = [](double) { return 0.0; };
  } else {
    throw std::invalid_argument("unknown scene '" + s.name + "' (hertz, partial or bilateral)");
  }
  return u;
}

}  // namespace chapter05
