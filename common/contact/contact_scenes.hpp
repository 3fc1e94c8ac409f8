// Loads and Dirichlet data of the two-body scenes of chapters 3 and 4 (chapter 3 notes).
#pragma once

#include <Eigen/Dense>

#include "common/fem/dirichlet.hpp"
#include "common/contact/manufactured_contact.hpp"
#include "common/contact/two_bodies.hpp"

namespace mortar {

struct SceneData {
  Eigen::VectorXd F;       // loads of both bodies
  DirichletData dirichlet;  // global dof numbering of TwoBodies
  std::vector<bool> prescribed_mask(int num_dofs) const;
};

// The manufactured solution: exact body forces, u prescribed on the top of body 1 and the
// bottom of body 2, exact tractions sigma n on the four lateral sides. K is then definite.
SceneData manufactured_scene(const TwoBodies& bodies, const ExactContact& exact);

// The same solution with u prescribed on every outer side (top, left and right of body 1;
// bottom, left and right of body 2): no side is free, so no corner mixes a support with a
// free edge, and the exact solution is the only solution (chapter 5's signorini and hertz-exact scenes).
SceneData manufactured_scene_all_sides(const TwoBodies& bodies, const ExactContact& exact);

// The patch test: a uniform pressure p on the top of body 1, rollers under body 2 (u_y = 0)
// and on the left sides of both (u_x = 0), the right sides free. The exact stress is
// sigma = diag(0, -p) in both bodies and u is linear: P1 contains it. Body 1 alone is free to
// move in y: only the contact constraints hold it, so K alone is singular here.
SceneData patch_test_scene(const TwoBodies& bodies, double pressure);

// Two bodies pressed between plates (chapter 5): the top of body 1 moved by (0, -delta), the
// bottom of body 2 clamped, the lateral sides free, no load. The contact decides the rest.
SceneData pressed_between_plates(const TwoBodies& bodies, double delta);

}  // namespace mortar
