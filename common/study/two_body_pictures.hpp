// Pictures of the two-body problem (chapters 3-5): the two meshes with their nonmatching
// traces on Gamma_c, the deformed configuration, and .vtu files for ParaView.
#pragma once

#include <functional>
#include <string>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/study/plot.hpp"

namespace mortar {

// Both meshes in an exploded view: body 1 lifted by a small gap so that the two traces on
// Gamma_c, which do not match, can be told apart; the nodes xi^1 of the non-mortar trace and
// xi^2 of the mortar trace marked, and, with merged_grid, the merged grid on the line between.
Figure two_body_meshes(const TwoBodies& bodies, const ContactInterface& gamma, bool merged_grid,
                       const std::string& title);

// The deformed configuration: both meshes moved by scale * u_h over the reference meshes in
// light grey; scale makes the largest displacement about 5% of L and is stated in the title.
// With an initial gap g(x) (chapter 5), body 1 is drawn lifted by g(x), so that its bottom is
// the curved surface the flat model stands for, [u.n] <= g reads as "no overlap" on the
// picture, and the lift is magnified by the same scale.
Figure deformed_two_bodies(const TwoBodies& bodies, const Eigen::VectorXd& u, const std::string& title,
                           const std::function<double(double)>& gap = nullptr);

// body1.vtu, body2.vtu (displacement, element stress) and contact.vtu (the pressure on the
// non-mortar trace) in folder.
void write_two_body_vtu(const std::string& folder, const TwoBodies& bodies, const Eigen::VectorXd& u,
                        const InterfaceCurve& pressure);

}  // namespace mortar
