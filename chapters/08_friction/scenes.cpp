#include "scenes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace chapter08 {

mortar::SceneData pressed_and_sheared(const mortar::TwoBodies& bodies, double delta, double Q, double L) {
  mortar::SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  const mortar::Mesh& top = bodies.body(0).mesh;
  const std::vector<int>& nodes = top.nodes_on(mortar::Side::top);  // ordered by x
  for (int a : nodes) {
    scene.dirichlet.dofs.push_back(bodies.dof(0, a, 1));
    scene.dirichlet.values.push_back(-delta);
  }
  // a uniform traction Q / L: each edge of the top side gives half its share to each end
  for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double h = top.nodes[nodes[k + 1]].x() - top.nodes[nodes[k]].x();
    scene.F[bodies.dof(0, nodes[k], 0)] += 0.5 * h * Q / L;
    scene.F[bodies.dof(0, nodes[k + 1], 0)] += 0.5 * h * Q / L;
  }
  for (int a : bodies.body(1).mesh.nodes_on(mortar::Side::bottom))
    for (int c = 0; c < 2; ++c) {
      scene.dirichlet.dofs.push_back(bodies.dof(1, a, c));
      scene.dirichlet.values.push_back(0.0);
    }
  return scene;
}

double cattaneo_exact_half_width(double L) { return L * std::sqrt(2.0) / 6; }

namespace {
// Step k of N prescribes the field of Q_k / (F P) = (k / N) q_ratio on every outer side: no load
// and no free side, the field decides the rest (chapter 5's hertz-exact, with a shear).
Scene cattaneo_exact_scene(const SceneParameters& p, const mortar::Material& body1, const mortar::Material& body2) {
  Scene s;
  s.name = p.name;
  const double x0 = 0.5 * p.L, R = p.R;
  s.gap = [x0, R](double x) { return (x - x0) * (x - x0) / (2 * R); };
  s.threshold = [](double) { return 0.0; };  // Coulomb: F lambda_n
  s.start_glued = true;
  s.steps = 1 + p.load_steps;
  for (int k = 0; k < s.steps; ++k)
    s.exact_steps.push_back(std::make_shared<const mortar::CattaneoHalfPlanes>(
        body1, body2, x0, cattaneo_exact_half_width(p.L), R, p.friction, static_cast<double>(k) / p.load_steps * p.q_ratio));
  const auto fields = s.exact_steps;
  s.step_data = [fields](const mortar::TwoBodies& bodies, int step, double) {
    return mortar::manufactured_scene_all_sides(bodies, *fields[static_cast<std::size_t>(step)]);
  };
  s.limit_data = [fields](const mortar::TwoBodies& bodies) { return mortar::manufactured_scene_all_sides(bodies, *fields[0]); };
  return s;
}
}  // namespace

Scene make_scene(const SceneParameters& p, const mortar::ManufacturedFriction& exact) {
  if (p.name == "cattaneo-exact") return cattaneo_exact_scene(p, exact.material(0), exact.material(1));
  Scene s;
  s.name = p.name;
  if (p.name == "manufactured") {
    s.gap = [](double) { return 0.0; };
    s.threshold = [&exact](double x) { return exact.threshold(x); };
    s.start_glued = true;
    s.step_data = [&exact](const mortar::TwoBodies& bodies, int, double) {
      return mortar::manufactured_scene_all_sides(bodies, exact);
    };
    s.limit_data = [&exact](const mortar::TwoBodies& bodies) { return mortar::manufactured_scene_all_sides(bodies, exact); };
    return s;
  }
  const double L = p.L, R = p.R;
  s.gap = [L, R](double x) { return (x - 0.5 * L) * (x - 0.5 * L) / (2 * R); };
  s.threshold = [](double) { return 0.0; };  // Coulomb: F lambda_n
  s.start_glued = true;
  const SceneParameters q = p;
  s.limit_data = [q](const mortar::TwoBodies& bodies) { return mortar::pressed_between_plates(bodies, q.delta); };
  if (p.proportional) {
    // P and Q together: step k of N presses by (k / N) delta and shears by (k / N) Q, Q from P
    s.steps = p.load_steps;
    s.step_data = [q](const mortar::TwoBodies& bodies, int step, double final_normal_force) {
      const double t = static_cast<double>(step + 1) / q.load_steps;
      return pressed_and_sheared(bodies, t * q.delta, t * q.q_ratio * q.friction * final_normal_force, q.L);
    };
    return s;
  }
  s.steps = 1 + p.load_steps;
  s.step_data = [q](const mortar::TwoBodies& bodies, int step, double normal_force) {
    const double Q = static_cast<double>(step) / q.load_steps * q.q_ratio * q.friction * normal_force;
    return pressed_and_sheared(bodies, q.delta, Q, q.L);
  };
  return s;
}

}  // namespace chapter08
