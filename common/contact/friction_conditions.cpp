#include "common/contact/friction_conditions.hpp"

#include <algorithm>
#include <cmath>

namespace mortar {

const char* node_status_name(NodeStatus s) {
  switch (s) {
    case NodeStatus::open: return "open";
    case NodeStatus::stick: return "stick";
    case NodeStatus::slip: return "slip";
  }
  return "?";
}

namespace {
bool in_contact(const NodalUnknowns& x, const NodalLaw& law) { return x.lambda_n + law.c_n * x.w_n > 0; }
double z_of(const NodalUnknowns& x, const NodalLaw& law) { return x.lambda_t + law.c_t * x.dw_t; }
double sign_of(double v) { return v >= 0 ? 1.0 : -1.0; }
}  // namespace

double friction_threshold(const NodalUnknowns& x, const NodalLaw& law) {
  if (law.law == FrictionLaw::tresca) return law.threshold;
  return law.friction * std::max(0.0, x.lambda_n + law.c_n * x.w_n);
}

NodeStatus node_status(const NodalUnknowns& x, const NodalLaw& law) {
  if (!in_contact(x, law)) return NodeStatus::open;
  return std::fabs(z_of(x, law)) < friction_threshold(x, law) ? NodeStatus::stick : NodeStatus::slip;
}

double normal_function(const NodalUnknowns& x, const NodalLaw& law) {
  return x.lambda_n - std::max(0.0, x.lambda_n + law.c_n * x.w_n);
}

double tangential_function(const NodalUnknowns& x, const NodalLaw& law) {
  const double s = friction_threshold(x, law), z = z_of(x, law);
  if (std::isinf(s)) return x.lambda_t - z;  // C_t / s as s grows: -c_t dw_t, no slip anywhere
  if (!in_contact(x, law) || !(s > 0)) return x.lambda_t;
  return std::max(s, std::fabs(z)) * x.lambda_t - s * z;
}

NodalResidual nodal_residual(const NodalUnknowns& x, const NodalLaw& law) {
  NodalResidual r;
  r.normal = normal_function(x, law);
  r.normal_size = std::max(std::fabs(x.lambda_n), law.c_n * std::fabs(x.w_n));
  const double s = friction_threshold(x, law);
  if (std::isinf(s) || !in_contact(x, law) || !(s > 0)) {  // -c_t dw_t (no slip), or lambda_t
    r.tangential = tangential_function(x, law);
    r.tangential_size = r.normal_size;
    return r;
  }
  r.tangential = tangential_function(x, law) / std::max(s, std::fabs(z_of(x, law)));
  r.tangential_size = s;
  return r;
}

NodalGradient normal_gradient(const NodalUnknowns& x, const NodalLaw& law) {
  NodalGradient g;
  if (in_contact(x, law)) g.w_n = -law.c_n;  // C_n = -c_n w_n
  else g.lambda_n = 1;                        // C_n = lambda_n
  return g;
}

NodalGradient tangential_gradient(const NodalUnknowns& x, const NodalLaw& law, bool bounded) {
  NodalGradient g;
  const NodeStatus status = node_status(x, law);
  const double s = friction_threshold(x, law), z = z_of(x, law);
  if (std::isinf(s)) {  // no slip, in contact or not: C_t / s = -c_t dw_t
    g.dw_t = -law.c_t;
    return g;
  }
  if (status == NodeStatus::open || !(s > 0)) {  // C_t = lambda_t
    g.lambda_t = 1;
    return g;
  }
  // ds / d(lambda_n, w_n): F (1, c_n) for Coulomb in contact, zero for Tresca
  const double ds_dlambda = law.law == FrictionLaw::coulomb ? law.friction : 0.0;
  double dC_ds = 0;
  if (status == NodeStatus::stick) {
    // C_t = s lambda_t - s z = -s c_t dw_t
    g.dw_t = -s * law.c_t;
    dC_ds = x.lambda_t - z;
  } else {
    // C_t = |z| lambda_t - s z
    double lt = x.lambda_t;
    if (bounded && s > 0 && std::fabs(lt) > s) lt = s * sign_of(lt);
    const double sl = sign_of(z) * lt;
    g.lambda_t = sl + std::fabs(z) - s;
    g.dw_t = law.c_t * (sl - s);
    dC_ds = -z;
  }
  g.lambda_n = dC_ds * ds_dlambda;
  g.w_n = dC_ds * ds_dlambda * law.c_n;
  return g;
}

}  // namespace mortar
