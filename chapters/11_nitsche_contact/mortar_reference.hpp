// The methods with multipliers, on the same level: chapter 5's integral mortar (standard basis
// of M_h^1, the constraint B u <= G, the primal-dual active set) and chapter 6's dual basis
// (diagonal D, the non-mortar normal dofs condensed, semismooth Newton in the displacements).
#pragma once

#include "level.hpp"

namespace chapter11 {

// dual = false: "mortar"; dual = true: "dual". The non-mortar side is --nonmortar.
MethodResult run_mortar(const Level& level, const Scene& scene, int nonmortar, bool dual);

}  // namespace chapter11
