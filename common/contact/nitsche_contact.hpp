// Contact without multipliers (chapter 11): Nitsche's method (Chouly and Hild, SIAM J. Numer.
// Anal. 51, 2013; Chouly, Hild and Renard, Math. Comp. 84, 2015) and penalty, for the two
// bodies of the course on nonmatching meshes.
//
// Signs as in the rest of the course: [u.n] = u^2_y - u^1_y (positive = penetration), the
// initial gap g >= 0, the pressure p = -sigma_N >= 0. The contact conditions
//     g - [u.n] >= 0,  p >= 0,  p (g - [u.n]) = 0
// are, for any gamma > 0, the one equation p = [P_gamma(u)]_+ with
//     P_gamma(u) = p(u) + gamma ([u.n] - g).
// (Chouly-Hild write P_gamma = sigma_n - gamma u_n and a negative part: the same equation with
// both signs turned.) Green's formula gives a(u, v) + int p [v.n] = L(v); putting p = [P_gamma]_+
// there and adding the consistent term that theta chooses gives Nitsche's method
//     a(u, v) - int (theta / gamma) p(u) p(v) + int (1 / gamma) [P_gamma(u)]_+ P_theta(v) = L(v),
//     P_theta(v) = theta p(v) + gamma [v.n],
// theta = 1 (symmetric: the derivative of an energy), 0, or -1 (skew-symmetric). The exact
// solution satisfies it for every v, which is what penalty lacks: penalty keeps only
//     a(u, v) + int [gamma ([u.n] - g)]_+ [v.n] = L(v),
// i.e. the same form with p(.) set to 0.
//
// p(u) is the traction of body 1, of body 2, or a mix: p(u) = w p^1(u) + (1 - w) p^2(u) with
// p^l(u) = -sigma^l_yy(u^l) on Gamma_c (both n^l are vertical), constant on each triangle for P1.
// gamma = gamma0 (w E1 / h1 + (1 - w) E2 / h2) on each merged segment, h_l the length of the
// trace element of body l over it: E / h where the traction is read.
//
// The integrals run over the merged grid of the two traces (chapter 4), where every trace is a
// single polynomial: on each segment [u.n] is linear and p(u) constant, so P_gamma is a
// quadratic when g is (the scenes' parabola; any other g is read through its quadratic
// interpolant on the segment to place the roots). The segment is cut at the roots of P_gamma
// and each part integrated by 3-point Gauss: exact, kink and all.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/nitsche_steps.hpp"
#include "common/contact/two_bodies.hpp"

namespace mortar {

struct NitscheOptions {
  bool penalty = false;  // true: drop p(.) (penalty), theta unused
  double theta = 1;      // 1, 0 or -1 (any value in [-1, 1] is a method)
  double gamma0 = 1;     // gamma = gamma0 E / h as above
  double fixed_gamma = 0;  // > 0: this gamma on every segment instead (penalty with gamma fixed)
  double body1_weight = 1;  // w: whose traction p(u) reads, 1 = body 1, 0 = body 2
  bool harmonic_weight = false;  // instead, w of harmonic_body1_weight on each segment's h1, h2
  int max_newton_steps = 60;
  double tol = 1e-10;  // Newton stops when |du| <= tol |u| (max norms)
  NitscheLinearSolver linear_solver = NitscheLinearSolver::condensed;  // nitsche_steps.hpp
  bool keep_last_matrix = false;  // NitscheSolution::last_matrix (for its conditioning)
};

// The weight of body 1 that makes gamma the smallest coercive choice for two materials:
// w = (h1 / E1) / (h1 / E1 + h2 / E2), so the softer body's traction dominates (Annavarapu,
// Hautefeuille and Dolbow, IJNME 2012, for interfaces).
double harmonic_body1_weight(double E1, double h1, double E2, double h2);

// One segment of the merged grid with what the contact terms need on it: the two triangles
// that touch it (local dofs 0-5 of body 1's, 6-11 of body 2's), the functional p(v) on those
// dofs (constant) and [v.n] at both ends (linear between).
struct NitscheSegment {
  double a = 0, b = 0;
  double gamma = 0;
  std::array<int, 12> dofs{};
  Eigen::Matrix<double, 12, 1> p = Eigen::Matrix<double, 12, 1>::Zero(), jump_a = p, jump_b = p;
  Eigen::Matrix<double, 12, 1> jump(double x) const {
    const double t = (x - a) / (b - a);
    return (1 - t) * jump_a + t * jump_b;
  }
};

std::vector<NitscheSegment> nitsche_segments(const TwoBodies& bodies, const NitscheOptions& options);

// The part of the residual and of its generalized derivative (the Newton matrix) that the contact
// term adds, at the displacement u (both bodies, all dofs): R += int ..., and for every segment
// its 12 x 12 block of triplets (zeros too, so that the pattern never changes).
void add_nitsche_terms(const std::vector<NitscheSegment>& segments, const std::function<double(double)>& gap,
                       const NitscheOptions& options, const Eigen::VectorXd& u, Eigen::VectorXd& residual,
                       std::vector<Eigen::Triplet<double>>* jacobian);

// The computed contact pressure [P_gamma(u_h)]_+ (penalty: its penalty force) on Gamma_c, as the
// list of pieces of the merged segments cut at the roots of P_gamma, each a quadratic given by
// its values at both ends and the middle.
struct PressurePiece {
  double a = 0, b = 0;
  double left = 0, middle = 0, right = 0;  // [P_gamma]_+ at a, (a + b) / 2, b
  bool active = false;  // P_gamma > 0 inside
  double at(double x) const;  // the quadratic through the three values
};
std::vector<PressurePiece> nitsche_pressure(const std::vector<NitscheSegment>& segments,
                                            const std::function<double(double)>& gap,
                                            const NitscheOptions& options, const Eigen::VectorXd& u);
double total_force(const std::vector<PressurePiece>& pressure);
// Half the length of the set where the pressure is positive (the contact zone's half-width when
// that set is one interval).
double contact_half_width(const std::vector<PressurePiece>& pressure);
// ||p_h - p||_{L2(Gamma_c)} and ||p||, each piece also cut at the exact pressure's kinks.
std::pair<double, double> pressure_l2_error(const std::vector<PressurePiece>& pressure,
                                            const std::function<double(double)>& exact,
                                            const std::vector<double>& exact_kinks);

struct NitscheSolution {
  Eigen::VectorXd u;  // both bodies, all dofs
  int newton_steps = 0;
  bool converged = false;
  std::string solver;  // the last step's linear solver (nitsche_steps.hpp)
  int lu_fallbacks = 0;  // symmetric steps whose matrix was not positive definite (solved by LU)
  std::string failure;   // why Newton stopped early (a singular step), or empty
  double residual = 0;  // max |R| / max |K u| over the free dofs at the end
  SparseMatrix last_matrix;  // keep_last_matrix: the last Newton step's matrix on the free dofs
  std::vector<NitscheSegment> segments;  // the segments it was solved on (for nitsche_pressure)
};

// Generalized Newton in the displacements alone, from `start` (both bodies, all dofs; its
// prescribed values are replaced by the scene's) or u = 0 on the free dofs: each step solves
// (K + C'(u)) du = -R(u) on the free dofs, as options.linear_solver says (nitsche_steps.hpp).
// The matrix is symmetric for theta = 1 and penalty (positive definite when gamma0 is large
// enough; else LU, the step counted), nonsymmetric for theta != 1.
NitscheSolution solve_nitsche_contact(const TwoBodies& bodies, const SceneData& scene,
                                      const std::function<double(double)>& gap, const NitscheOptions& options,
                                      const Eigen::VectorXd* start = nullptr);

}  // namespace mortar
