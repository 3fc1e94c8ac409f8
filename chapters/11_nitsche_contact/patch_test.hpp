// The patch test (chapters 3 and 4) for the methods without multipliers: a uniform pressure p on
// top of body 1, rollers below body 2 and on the left sides, meshes with h2 / h1 = 3 / 7. The
// exact stress is sigma_22 = -p in both bodies and P1 holds it; Nitsche is consistent, so it
// must give it to round-off for every theta, gamma0 and traction weight. Penalty transmits p
// through a uniform penetration p / gamma: exact stress too, as long as gamma is the same
// along Gamma_c (patch_test.cpp makes it so, with --jitter too). Body 1 is held by the contact
// alone, loaded by the pressure on its top.
#pragma once

#include "common/contact/nitsche_contact.hpp"
#include "options.hpp"

namespace chapter11 {

// max over the triangles of both bodies of |sigma_22 + p| / p, and the Newton steps taken.
struct PatchResult {
  double rel_error = 0;
  int newton_steps = 0;
};
PatchResult nitsche_patch_test(const Options& o, const mortar::NitscheOptions& method);

}  // namespace chapter11
