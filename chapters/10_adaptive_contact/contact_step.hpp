// One SOLVE of the adaptive loop: chapter 6's dual mortar contact on the meshes the bodies have
// now. The traces on Gamma_c are read off the meshes as they are (each body refined on its own,
// so they stop matching in new ways at every step); the merged grid, the dual basis of M_h^1
// and D, M are rebuilt from them; the non-mortar normal dofs are condensed and the semismooth
// Newton method finds the active set.
//
// Nested iteration: the previous step's solution, carried over, gives Newton its first active
// set. Row i starts active when lambda~_i + c_i w~_i > 0 (the same test every Newton step
// makes), lambda~ the previous multiplier at row i's node and w~ the weighted gap of the
// previous displacement prolonged to the new meshes. A direct solver needs no starting
// displacement; the start is what it saves: the Newton steps.
#pragma once

#include <Eigen/Dense>

#include "scenes.hpp"
#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"

namespace chapter10 {

struct NestedStart {
  mortar::InterfaceCurve pressure;  // the previous multipliers at their nodes (zero outside)
  Eigen::VectorXd u;                // the previous displacement on the new meshes (may be empty)
};

struct ContactStep {
  mortar::TwoBodies bodies;
  mortar::ContactInterface gamma;
  mortar::Constraints constraints;
  Eigen::VectorXd u;       // both bodies, every dof
  Eigen::VectorXd lambda;  // one per constraint row: the dual coefficients, a pressure
  mortar::InterfaceCurve pressure;
  int newton_steps = 0;    // solves, one factorization each
  int active_rows = 0;
  double solve_s = 0;      // assembly, interface, condensation and Newton
};

// Gamma_c where both bodies have it: each trace cut to the part of the line the other body
// also covers (the punch's body 2 reaches beyond body 1), so both traces share their end
// points a1, a2 (paper section 3). The cut must fall on nodes of both traces.
mortar::ContactInterface overlap_dual_interface(const mortar::TwoBodies& bodies, int nonmortar);

ContactStep solve_contact_step(const Scene& scene, mortar::Mesh mesh1, mortar::Mesh mesh2, int nonmortar,
                               const NestedStart* start);

// The start the next step takes from this one; u_prolonged may be empty.
NestedStart nested_start(const ContactStep& step, Eigen::VectorXd u_prolonged);

// The strain energy 1/2 u.K u of both bodies: the norm the loop's target is relative to, and the
// punch's error measure (study.hpp).
double strain_energy(const ContactStep& step);

}  // namespace chapter10
