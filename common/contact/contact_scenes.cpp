#include "common/contact/contact_scenes.hpp"

namespace mortar {

std::vector<bool> SceneData::prescribed_mask(int num_dofs) const {
  std::vector<bool> mask(num_dofs, false);
  for (int d : dirichlet.dofs) mask[d] = true;
  return mask;
}

namespace {
// Appends body l's data to the global scene: its load vector and its prescribed dofs.
void add_body(SceneData& scene, const TwoBodies& bodies, int l, const Eigen::VectorXd& F,
              const DirichletData& d) {
  scene.F.segment(bodies.offset(l), F.size()) += F;
  for (std::size_t k = 0; k < d.dofs.size(); ++k) {
    scene.dirichlet.dofs.push_back(bodies.offset(l) + d.dofs[k]);
    scene.dirichlet.values.push_back(d.values[k]);
  }
}
}  // namespace

SceneData manufactured_scene(const TwoBodies& bodies, const ExactContact& exact) {
  SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  for (int l = 0; l < 2; ++l) {
    const Mesh& mesh = bodies.body(l).mesh;
    Eigen::VectorXd F = body_force_vector(
        mesh, [&](const Eigen::Vector2d& p) { return exact.body_force(l, p); }, 4, exact.body_force_breaks());
    // (the explicit return type matters: an Eigen product expression would outlive its operands)
    add_traction(F, mesh, Side::left,
                 [&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return exact.stress(l, p).col(0) * -1.0; }, 3);
    add_traction(F, mesh, Side::right,
                 [&](const Eigen::Vector2d& p) -> Eigen::Vector2d { return exact.stress(l, p).col(0); }, 3);
    DirichletData d;
    prescribe_on_sides(d, mesh, {l == 0 ? Side::top : Side::bottom},
                       [&](const Eigen::Vector2d& p) { return exact.u(l, p); });
    add_body(scene, bodies, l, F, d);
  }
  return scene;
}

SceneData manufactured_scene_all_sides(const TwoBodies& bodies, const ExactContact& exact) {
  SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  for (int l = 0; l < 2; ++l) {
    const Mesh& mesh = bodies.body(l).mesh;
    const Eigen::VectorXd F =
        exact.has_body_force()
            ? body_force_vector(mesh, [&](const Eigen::Vector2d& p) { return exact.body_force(l, p); }, 4,
                                exact.body_force_breaks())
            : Eigen::VectorXd::Zero(mesh.num_dofs());
    DirichletData d;
    prescribe_on_sides(d, mesh, {l == 0 ? Side::top : Side::bottom, Side::left, Side::right},
                       [&](const Eigen::Vector2d& p) { return exact.u(l, p); });
    add_body(scene, bodies, l, F, d);
  }
  return scene;
}

SceneData patch_test_scene(const TwoBodies& bodies, double pressure) {
  SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  for (int l = 0; l < 2; ++l) {
    const Mesh& mesh = bodies.body(l).mesh;
    Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
    DirichletData d;
    if (l == 0)
      add_traction(F, mesh, Side::top, [&](const Eigen::Vector2d&) { return Eigen::Vector2d(0, -pressure); }, 1);
    for (int a : mesh.nodes_on(Side::left)) {
      d.dofs.push_back(2 * a);
      d.values.push_back(0.0);
    }
    if (l == 1)
      for (int a : mesh.nodes_on(Side::bottom)) {
        d.dofs.push_back(2 * a + 1);
        d.values.push_back(0.0);
      }
    add_body(scene, bodies, l, F, d);
  }
  return scene;
}

SceneData pressed_between_plates(const TwoBodies& bodies, double delta) {
  SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  const auto hold = [&](int l, Side side, const Eigen::Vector2d& value) {
    for (int a : bodies.body(l).mesh.nodes_on(side))
      for (int c = 0; c < 2; ++c) {
        scene.dirichlet.dofs.push_back(bodies.dof(l, a, c));
        scene.dirichlet.values.push_back(value[c]);
      }
  };
  hold(0, Side::top, Eigen::Vector2d(0, -delta));
  hold(1, Side::bottom, Eigen::Vector2d(0, 0));
  return scene;
}

}  // namespace mortar
