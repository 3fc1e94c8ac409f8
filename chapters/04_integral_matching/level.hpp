// One level of chapter 4: two bodies glued by integral (mortar) matching, step by step.
#pragma once

#include "common/contact/bilateral_contact.hpp"

namespace chapter04 {

// The bodies are meshed and loaded; every step from Gamma_c to (u_h, lambda_h) is here, in the
// order of the lecture (README.md, "The program"). options.matching is not read: this chapter
// always glues by integral matching.
mortar::BilateralSolution solve_integral_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                  const mortar::BilateralOptions& options);

}  // namespace chapter04
