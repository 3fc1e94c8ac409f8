// One refinement level of chapter 2: mesh, assemble, load, eliminate, solve, measure.
#pragma once

#include <Eigen/Dense>

#include "common/fem/errors.hpp"
#include "common/fem/mesh.hpp"
#include "common/linalg/physical_limit.hpp"
#include "common/linalg/spd_solver.hpp"
#include "manufactured_solution.hpp"

namespace chapter02 {

struct LevelSetup {
  int n = 8;            // n x n cells on the unit square
  double jitter = 0;    // fraction of h
  mortar::SpdBackend backend = mortar::fastest_spd_backend();
};

struct LevelResult {
  mortar::Mesh mesh;
  Eigen::VectorXd u;          // nodal displacements, 2 per node
  int dofs = 0;               // all nodal dofs, Dirichlet ones included (2 per node)
  double time_s = 0;          // assembly + loads + elimination + factorization + solve
  double limit_s = 0;         // assembly + Cholesky factorization + solve of K alone
  mortar::TimedLevel timing{};  // both, with their spread, phases and memory peaks
  mortar::ErrorNorms norms;
};

LevelResult solve_level(const LevelSetup& setup, const mortar::Material& material,
                        const ManufacturedSolution& exact);

}  // namespace chapter02
