#include "exercise.hpp"

namespace exercise {

SegmentTerm nitsche_segment_term(const Segment& s, double theta, const std::function<double(double)>& gap,
                                 const Vector12& u) {
  // Your code here: P_gamma(u) on [a, b]; where it changes sign (its roots: g is not a
  // quadratic, so find them numerically); on each piece where it is positive, a Gauss rule
  // exact for the integrand's degree; the term -(theta / gamma) p p^T on the whole segment.
  (void)s;
  (void)theta;
  (void)gap;
  (void)u;
  return {};
}

}  // namespace exercise
