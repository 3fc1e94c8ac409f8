#include "scenes.hpp"

#include <cmath>
#include <stdexcept>

#include "common/contact/hertz_half_planes.hpp"
#include "common/contact/manufactured_contact.hpp"

namespace chapter05 {

double hertz_exact_half_width(double L) { return L * std::sqrt(2.0) / 6; }

std::unique_ptr<const mortar::ExactContact> make_exact(const SceneParameters& s, const mortar::Material& body1,
                                                       const mortar::Material& body2) {
  if (s.name == "hertz-exact")
    return std::make_unique<mortar::HertzHalfPlanes>(body1, body2, s.L / 2, hertz_exact_half_width(s.L), s.R);
  if (s.name == "signorini")
    return std::make_unique<mortar::ManufacturedContact>(
        body1, body2, mortar::signorini_profile(s.L, mortar::signorini_contact_point(s.L)), s.L);
  return std::make_unique<mortar::ManufacturedContact>(body1, body2, s.L);
}

UnilateralScene make_scene(const SceneParameters& s, const mortar::TwoBodies& bodies,
                           const mortar::ExactContact& exact) {
  UnilateralScene u;
  const double x0 = s.L / 2, R = s.R;
  const auto hertz_gap = [x0, R](double x) { return (x - x0) * (x - x0) / (2 * R); };
  if (s.name == "hertz") {
    u.data = mortar::pressed_between_plates(bodies, s.delta);
    u.gap = hertz_gap;
  } else if (s.name == "hertz-exact") {
    // the half-planes' displacement on every outer side, no load: the field decides the rest
    u.data = mortar::manufactured_scene_all_sides(bodies, exact);
    u.gap = hertz_gap;
  } else if (s.name == "partial") {
    u.data = mortar::pressed_between_plates(bodies, s.delta);
    const double slope = 2 * s.delta / s.L;
    u.gap = [slope](double x) { return slope * x; };
  } else if (s.name == "bilateral") {
    u.data = mortar::manufactured_scene(bodies, exact);
    u.gap = [](double) { return 0.0; };
  } else if (s.name == "signorini") {
    u.data = mortar::manufactured_scene_all_sides(bodies, exact);
    const double L = s.L;
    u.gap = [L](double x) { return mortar::signorini_gap(L, x); };
  } else {
    throw std::invalid_argument("unknown scene '" + s.name + "' (hertz, hertz-exact, partial, bilateral or signorini)");
  }
  return u;
}

}  // namespace chapter05
