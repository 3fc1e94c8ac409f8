// Pictures of the two-body problem (chapters 3-5): the two meshes with their nonmatching
// traces on Gamma_c, the deformed configuration, and .vtu files for ParaView.
#pragma once

#include <functional>
#include <string>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/study/plot.hpp"

namespace mortar {

// Both meshes, body 1 lifted by a small gap so that the two traces on Gamma_c can be told
// apart on the bodies, and below body 2 a strip of number lines: the nodes xi^1 of the
// non-mortar trace (one pointwise row each, or the multipliers of M_h^1), the nodes xi^2 of
// the mortar trace, and for integral matching their merged grid, every node of both.
Figure two_body_meshes(const TwoBodies& bodies, const ContactInterface& gamma, Matching matching,
                       const std::string& title);

// The deformed configuration: both meshes moved by scale * u_h over the reference meshes in
// light grey; scale makes the largest displacement about 5% of L and is stated in the title.
// With an initial gap g(x) (chapter 5), body 1 is drawn lifted by g(x), so that its bottom is
// the curved surface the flat model stands for, [u.n] <= g reads as "no overlap" on the
// picture, and the lift is magnified by the same scale.
Figure deformed_two_bodies(const TwoBodies& bodies, const Eigen::VectorXd& u, const std::string& title,
                           const std::function<double(double)>& gap = nullptr);

// A P1 curve on Gamma_c evaluated at the points x (inside its range).
std::vector<double> curve_at(const InterfaceCurve& curve, const std::vector<double>& x);

// body1.vtu, body2.vtu (displacement; sigma_xx, sigma_yy, sigma_xy, von Mises) and
// contact.vtu: Gamma_c as line cells between the merged-grid nodes (the jump's points) with
// the pressure (P1 on xi^1, exact there too) and the normal jump [u_h.n] as point data.
// Binary (base64) arrays: the finest levels would give tens of megabytes as text.
void write_two_body_vtu(const std::string& folder, const TwoBodies& bodies, const Eigen::VectorXd& u,
                        const InterfaceCurve& pressure, const InterfaceCurve& jump);

}  // namespace mortar
