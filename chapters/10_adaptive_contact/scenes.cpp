#include "scenes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/contact/hertz_half_planes.hpp"
#include "common/contact/manufactured_contact.hpp"

namespace chapter10 {

double small_zone_half_width(double L) { return L * std::sqrt(2.0) / 29; }

Scene::Scene(const SceneOptions& o) : o_(o) {
  const mortar::Material m1 = material(0), m2 = material(1);
  if (o.name == "hertz-exact")
    exact_ = std::make_unique<mortar::HertzHalfPlanes>(m1, m2, o.bodies.L / 2, small_zone_half_width(o.bodies.L), o.R);
  else if (o.name == "bilateral")
    exact_ = std::make_unique<mortar::ManufacturedContact>(m1, m2, o.bodies.L);
  else if (o.name != "punch")
    throw std::invalid_argument("unknown scene '" + o.name + "' (hertz-exact, bilateral or punch)");
}

mortar::Material Scene::material(int l) const {
  return l == 0 ? mortar::Material(o_.bodies.E1, o_.bodies.nu1) : mortar::Material(o_.bodies.E2, o_.bodies.nu2);
}

namespace {
int cells(double length, double h) { return std::max(1, static_cast<int>(std::lround(length / h))); }

// The punch's supports: body 1's top moved down by delta and body 2's bottom held in y, both
// free to slide (rollers) except at their node x = xm, held in x against rigid sliding. A
// roller corner is regular (mirrored, it is a straight free edge), so body 1's corners on
// Gamma_c are the only singular points (a clamped corner would be one too, exponent 0.71).
mortar::SceneData punch_supports(const mortar::TwoBodies& bodies, double xm, double delta) {
  mortar::SceneData scene;
  scene.F = Eigen::VectorXd::Zero(bodies.num_dofs());
  for (int l = 0; l < 2; ++l) {
    const mortar::Mesh& mesh = bodies.body(l).mesh;
    const std::vector<int>& side = mesh.nodes_on(l == 0 ? mortar::Side::top : mortar::Side::bottom);
    const auto middle = std::min_element(side.begin(), side.end(), [&](int a, int b) {
      return std::fabs(mesh.nodes[a].x() - xm) < std::fabs(mesh.nodes[b].x() - xm);
    });
    for (int node : side) {
      scene.dirichlet.dofs.push_back(bodies.dof(l, node, 1));
      scene.dirichlet.values.push_back(l == 0 ? -delta : 0.0);
    }
    scene.dirichlet.dofs.push_back(bodies.dof(l, *middle, 0));
    scene.dirichlet.values.push_back(0.0);
  }
  return scene;
}
}  // namespace

mortar::RectangleSpec Scene::first_mesh(int l, int refinements) const {
  const int n1 = o_.n0 << refinements;
  mortar::RectangleSpec s;
  if (o_.name == "punch") {
    // body 1 is w = L/4 wide and as tall; body 2's columns must hold nodes at L/2 -+ w/2,
    // where body 1's corners sit, so their number is a multiple of 8
    const double w = o_.bodies.L / 4, h1 = w / n1;
    if (l == 0) {
      s.x0 = o_.bodies.L / 2 - w / 2;
      s.x1 = o_.bodies.L / 2 + w / 2;
      s.y1 = w;
      s.nx = s.ny = n1;
      s.jitter = o_.bodies.jitter;
    } else {
      s.x1 = o_.bodies.L;
      s.y0 = -o_.bodies.H2;
      s.y1 = 0;
      s.nx = 8 * cells(o_.bodies.L / 8, o_.bodies.h_ratio * h1);
      s.ny = cells(o_.bodies.H2, o_.bodies.L / s.nx);
    }
    return s;
  }
  s.x1 = o_.bodies.L;
  s.jitter = o_.bodies.jitter;
  if (l == 0) {
    s.y1 = o_.bodies.H1;
    s.nx = n1;
    s.ny = cells(o_.bodies.H1, o_.bodies.L / n1);
  } else {
    s.y0 = -o_.bodies.H2;
    s.y1 = 0;
    s.nx = cells(o_.bodies.L, o_.bodies.h_ratio * o_.bodies.L / n1);
    s.ny = cells(o_.bodies.H2, o_.bodies.L / s.nx);
  }
  return s;
}

mortar::SceneData Scene::data(const mortar::TwoBodies& bodies) const {
  if (o_.name == "hertz-exact") return mortar::manufactured_scene_all_sides(bodies, *exact_);
  if (o_.name == "bilateral") return mortar::manufactured_scene(bodies, *exact_);
  return punch_supports(bodies, o_.bodies.L / 2, o_.delta);
}

double Scene::gap(double x) const {
  if (o_.name != "hertz-exact") return 0.0;
  const double X = x - o_.bodies.L / 2;
  return X * X / (2 * o_.R);
}

mortar::EstimatorData Scene::estimator_data() const {
  mortar::EstimatorData d;
  d.unilateral = unilateral();
  d.gap = [this](double x) { return gap(x); };
  using mortar::Side;
  if (o_.name == "bilateral") {
    // chapter 4's scene: a body force, and the exact traction sigma n on the lateral sides
    for (int l = 0; l < 2; ++l) {
      const mortar::ExactContact* e = exact_.get();
      d.body_force[l] = [e, l](const Eigen::Vector2d& p) { return e->body_force(l, p); };
      d.neumann[l].emplace_back(Side::left,
                                [e, l](const Eigen::Vector2d& p) -> Eigen::Vector2d { return -e->stress(l, p).col(0); });
      d.neumann[l].emplace_back(Side::right,
                                [e, l](const Eigen::Vector2d& p) -> Eigen::Vector2d { return e->stress(l, p).col(0); });
    }
  } else if (o_.name == "punch") {
    // free sides; the rollers' tangential traction is zero too (their normal one is the reaction)
    const auto free = [](const Eigen::Vector2d&) -> Eigen::Vector2d { return Eigen::Vector2d::Zero(); };
    for (int l = 0; l < 2; ++l)
      for (Side s : {Side::left, Side::right}) d.neumann[l].emplace_back(s, free);
  }
  return d;
}

}  // namespace chapter10
