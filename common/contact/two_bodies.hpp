// Two bodies in plane strain meeting along Gamma_c = (0, L) x {0} (README.md, "Notation"):
// body 1 above, Omega1 = (0, L) x (0, H1), body 2 below, Omega2 = (0, L) x (-H2, 0). One
// global unknown vector holds both: body 1's dofs first, then body 2's.
#pragma once

#include <array>
#include <vector>

#include "common/fem/mesh.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

struct Body {
  Mesh mesh;
  Material material;
};

// Sizes of the two meshes: n_l cells along Gamma_c, m_l across, nodes on Gamma_c jittered
// along it (so the two traces differ even for equal n), corners fixed.
struct TwoBodyGeometry {
  double L = 1, H1 = 0.5, H2 = 0.5;
  int n1 = 12, m1 = 6, n2 = 8, m2 = 4;
  double jitter = 0;
  int degree = 1;  // q of both bodies: P1, or P2 (chapter 7) on the same triangles
};

class TwoBodies {
 public:
  TwoBodies(Body body1, Body body2);
  // l = 0 for body 1 (upper), 1 for body 2 (lower)
  const Body& body(int l) const { return bodies_[l]; }
  int offset(int l) const { return l == 0 ? 0 : bodies_[0].mesh.num_dofs(); }
  int num_dofs() const { return bodies_[0].mesh.num_dofs() + bodies_[1].mesh.num_dofs(); }
  int dof(int l, int node, int component) const { return offset(l) + 2 * node + component; }
  // Outward normal of body l on Gamma_c: n1 = (0, -1), n2 = (0, 1).
  static double normal_y(int l) { return l == 0 ? -1.0 : 1.0; }

  // Block-diagonal K of both bodies (no coupling: that is the constraints' job).
  SparseMatrix stiffness() const;
  // The part of a global vector that belongs to body l.
  Eigen::VectorXd part(const Eigen::VectorXd& u, int l) const;
  double max_edge_length() const;

 private:
  std::array<Body, 2> bodies_;
};

// The rectangle of body l (0 upper, 1 lower) as rectangle_mesh takes it: its P1 mesh, or a band
// of its cell rows (rectangle_band).
RectangleSpec body_rectangle(const TwoBodyGeometry& g, int l);
TwoBodies make_two_bodies(const TwoBodyGeometry& g, const Material& body1, const Material& body2);

}  // namespace mortar
