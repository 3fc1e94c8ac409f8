// The linear solve of every Newton step of chapter 9, on the condensed system A v = r with
// A = T^T K T (distributed_condensation.hpp), and w_i = 0 on the active pivots.
//
// A is never formed. CG only needs products A x = T^T (K (T x)): one product with K, the
// assembled stiffness, and two with T, the identity but for its pivot rows. Its preconditioner
// follows from A^{-1} = T^{-1} K^{-1} T^{-T}: T^{-1} M^{-1} T^{-T}, with M^{-1} PETSc's
// preconditioner of K itself (GAMG by default, or MUMPS's Cholesky, or any -pc_type). So
// algebraic multigrid sees an ordinary elasticity matrix with its rigid-body modes, built once
// per level (on K, or on K glued along the first active set: below). T^{-1} costs nothing: T = I - E
// with E nonzero only in pivot rows and non-pivot columns, so E^2 = 0 and T^{-1} = I + E = 2I - T.
//
// A Newton step fixes v = 0 on the active pivots P_A. CG then works on the free unknowns, with
// the operator and the preconditioner both projected (Pi: zero on P_A):
//
//     A_step x = Pi A Pi x + (I - Pi) x,     M_step^{-1} r = Pi T^{-1} M^{-1} T^{-T} Pi r + (I - Pi) r.
//
// On the free unknowns M_step^{-1} inverts a Schur complement of T^T M T, not its restriction:
// the two differ by a term of rank at most the number of fixed pivots, the glued zone's modes.
// With M built on K the final solves grew from 43 to 99 iterations (27k to 1.7M unknowns, Hertz),
// and like h^-0.43 with every pivot fixed (the manufactured scene); built on K glued along the
// active set (glued_stiffness.hpp) they stay at 22-29 (chapter 9's notes).
#pragma once

#include <petscksp.h>

#include <string>
#include <utility>
#include <vector>

namespace chapter09 {

class CondensedSolver {
 public:
  // K: the stiffness with its near-null space attached (or any SPD matrix); T: u = T v + g, or
  // nullptr for T = I. `rtol` and the command line configure the solver as every solve of the
  // chapter is configured: CG outside, GAMG (or the command line's -pc_type) on K inside.
  // `built_on`: the matrix M is built on, K by default, or K glued along an active set
  // (glued_stiffness.hpp), which the projected preconditioner inverts far better.
  CondensedSolver(Mat K, Mat T, double rtol, Mat built_on = nullptr);
  ~CondensedSolver();
  CondensedSolver(const CondensedSolver&) = delete;
  CondensedSolver& operator=(const CondensedSolver&) = delete;

  // Builds the preconditioner (of K, or of `built_on`) once, and tells PETSc to keep it: the
  // matrix it is built on does not change within a level.
  void set_up();
  // How many times the preconditioner was built: the calls of set_up() (one per level, not one
  // per Newton step), and any rebuild PETSc made on its own since, seen in the objects it built
  // (for GAMG and PCMG the operators and interpolations of every level, for a factorization its
  // factor; other types are not probed). With PETSc told to keep it, the second part stays 0
  // unless that is undone. Checked after every solve.
  int setups() const { return setups_; }
  // The rows fixed at v = 0 from now on: this rank's active pivots.
  void fix(const std::vector<PetscInt>& owned_rows) { fixed_ = owned_rows; }
  // CG on A_step v = Pi rhs from the given v (both set to 0 on the fixed rows first), to
  // ||B r|| <= rtol ||B rhs|| and ||r|| <= rtol ||rhs|| (B the preconditioner, r the residual),
  // or with `from_start` to ||B r|| <= rtol times its initial value.
  // Returns the iterations; throws with PETSc's reason, the iterations and the residual when the
  // true residual misses the tolerance, whatever PETSc's own test said.
  int solve(Vec rhs, Vec v, double rtol, bool from_start);
  // y = A x, nothing fixed.
  void apply_A(Vec x, Vec y);

  std::string ksp_type() const;
  std::string pc_type() const;  // of PETSc's preconditioner (inside the shell)
  double final_rtol() const { return rtol_; }

 private:
  static PetscErrorCode mult(Mat shell, Vec x, Vec y);
  static PetscErrorCode precondition(PC pc, Vec r, Vec z);
  static PetscErrorCode converged(KSP ksp, PetscInt it, PetscReal rnorm, KSPConvergedReason* reason, void* context);
  double norm_2(Vec x);
  double norm(Vec x);
  Vec residual(Vec rhs, Vec v);
  void zero_fixed(Vec x) const;
  void copy_fixed(Vec from, Vec to) const;
  void apply_T(Vec x, Vec y, bool transpose, bool inverse);
  using Fingerprint = std::vector<std::pair<PetscObjectId, PetscObjectState>>;
  Fingerprint fingerprint() const;

  Mat K_, T_, shell_ = nullptr;
  KSP ksp_ = nullptr;
  PC inner_ = nullptr;
  Vec x_, u_, Ku_, rho_, z_;
  std::vector<PetscInt> fixed_;
  PetscInt first_ = 0;
  double rtol_ = 0;
  int setups_ = 0;
  Fingerprint built_;  // the preconditioner's objects when last built
  // the solve's test in the force residual: ||rho|| <= rtol scale (converged())
  struct ForceTest {
    void* standard = nullptr;  // PETSc's default test, run first
    double rtol = 0, scale = 0;  // rtol = 0: no force test (a loose solve)
    double first_met = -1;     // PETSc's norm where its own test was first met
  } force_;
};

}  // namespace chapter09
