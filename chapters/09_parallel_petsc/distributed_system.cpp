#include "distributed_system.hpp"

#include <algorithm>

#include "common/fem/p1_elasticity.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

Mat create_matrix(const Ownership& rows, PetscInt per_row) {
  Mat M;
  check(MatCreate(PETSC_COMM_WORLD, &M), "MatCreate");
  check(MatSetSizes(M, rows.local(), rows.local(), rows.size, rows.size), "MatSetSizes");
  check(MatSetBlockSize(M, 2), "MatSetBlockSize");
  check(MatSetType(M, MATAIJ), "MatSetType");
  check(MatSeqAIJSetPreallocation(M, per_row, nullptr), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(M, per_row, nullptr, per_row, nullptr), "MatMPIAIJSetPreallocation");
  check(MatSetOption(M, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
  return M;
}

DistributedSystem::~DistributedSystem() {
  if (K != nullptr) MatDestroy(&K);
  if (f != nullptr) VecDestroy(&f);
  if (coordinates != nullptr) VecDestroy(&coordinates);
}

namespace {
// K without boundary conditions: the triangles of this rank's band, in global dofs.
void add_element_matrices(Mat K, const Part& part) {
  for (int l = 0; l < 2; ++l) {
    const mortar::Mesh& mesh = part.bodies.body(l).mesh;
    const mortar::Material& material = part.bodies.body(l).material;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const auto& tri = mesh.triangles[t];
      const mortar::ElementMatrix Ke = mortar::element_stiffness(mortar::triangle_vertices(mesh, t), material);
      PetscInt dofs[6];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 2; ++c) dofs[2 * a + c] = part.global(part.bodies.dof(l, tri[a], c));
      PetscScalar values[36];
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) values[6 * i + j] = Ke(i, j);
      check(MatSetValues(K, 6, dofs, 6, dofs, values, ADD_VALUES), "MatSetValues (element matrix)");
    }
  }
  check(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

void assemble_vector(Vec v) {
  check(VecAssemblyBegin(v), "VecAssemblyBegin");
  check(VecAssemblyEnd(v), "VecAssemblyEnd");
}
}  // namespace

void assemble(DistributedSystem& s, const Ownership& rows, const Part& part, const mortar::SceneData& scene) {
  s.rows = rows;
  // A P1 node of these meshes has at most 6 neighbours: 14 columns per row; a row near the
  // end of a rank's range has some of them on the next rank.
  s.K = create_matrix(s.rows, 14);
  check(MatSetOption(s.K, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  add_element_matrices(s.K, part);

  // Loads: the band's, added (the row above the band is shared with the next rank).
  // Coordinates: each owned node's.
  check(VecCreateMPI(PETSC_COMM_WORLD, s.rows.local(), s.rows.size, &s.f), "VecCreateMPI");
  check(VecSetBlockSize(s.f, 2), "VecSetBlockSize");
  check(VecSet(s.f, 0.0), "VecSet");
  check(VecDuplicate(s.f, &s.coordinates), "VecDuplicate");
  for (int d = 0; d < part.bodies.num_dofs(); ++d) {
    const PetscInt global = part.global(d);
    if (scene.F[d] != 0) check(VecSetValue(s.f, global, scene.F[d], ADD_VALUES), "VecSetValue");
    if (!s.rows.owns(global)) continue;
    const int l = d < part.bodies.offset(1) ? 0 : 1;
    const int node = (d - part.bodies.offset(l)) / 2;
    check(VecSetValue(s.coordinates, global, part.bodies.body(l).mesh.nodes[node][d % 2], INSERT_VALUES),
          "VecSetValue");
  }
  assemble_vector(s.f);
  assemble_vector(s.coordinates);

  // Dirichlet: the prescribed values on the diagonal's scale, K stays symmetric. The owned
  // prescribed dofs (a band's side nodes in the shared row are the next rank's).
  Vec diagonal;
  check(VecDuplicate(s.f, &diagonal), "VecDuplicate");
  check(MatGetDiagonal(s.K, diagonal), "MatGetDiagonal");
  check(VecMax(diagonal, nullptr, &s.diagonal), "VecMax");
  check(VecDestroy(&diagonal), "VecDestroy");
  std::vector<PetscInt> fixed;
  Vec u_d;
  check(VecDuplicate(s.f, &u_d), "VecDuplicate");
  check(VecSet(u_d, 0.0), "VecSet");
  for (std::size_t k = 0; k < scene.dirichlet.dofs.size(); ++k) {
    const PetscInt global = part.global(scene.dirichlet.dofs[k]);
    if (!s.rows.owns(global)) continue;
    fixed.push_back(global);
    check(VecSetValue(u_d, global, scene.dirichlet.values[k], INSERT_VALUES), "VecSetValue");
  }
  assemble_vector(u_d);
  std::sort(fixed.begin(), fixed.end());  // a corner on two prescribed sides comes twice
  fixed.erase(std::unique(fixed.begin(), fixed.end()), fixed.end());
  check(MatZeroRowsColumns(s.K, static_cast<PetscInt>(fixed.size()), fixed.data(), s.diagonal, u_d, s.f),
        "MatZeroRowsColumns (Dirichlet)");
  check(VecDestroy(&u_d), "VecDestroy");

  // the rigid-body modes, for algebraic multigrid (exercise 12)
  MatNullSpace modes;
  check(MatNullSpaceCreateRigidBody(s.coordinates, &modes), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(s.K, modes), "MatSetNearNullSpace");
  check(MatNullSpaceDestroy(&modes), "MatNullSpaceDestroy");
}

}  // namespace chapter09
