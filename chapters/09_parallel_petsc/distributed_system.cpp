#include "distributed_system.hpp"

#include <cmath>
#include <limits>

#include "common/fem/p1_elasticity.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

Ownership split_by_nodes(PetscInt dofs) { return split_by_nodes(dofs, rank(), ranks()); }

Ownership split_by_nodes(PetscInt dofs, int r, int n) {
  const PetscInt nodes = dofs / 2;
  // the first nodes % n ranks get one node more
  const PetscInt base = nodes / n, extra = nodes % n;
  const PetscInt first_node = r * base + std::min<PetscInt>(r, extra);
  const PetscInt count = base + (r < extra ? 1 : 0);
  return {2 * first_node, 2 * (first_node + count), dofs};
}

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
// K without boundary conditions: the owned triangles of both bodies.
void add_element_matrices(Mat K, const Ownership& rows, const mortar::TwoBodies& bodies) {
  for (int l = 0; l < 2; ++l) {
    const mortar::Mesh& mesh = bodies.body(l).mesh;
    const mortar::Material& material = bodies.body(l).material;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
      const auto& tri = mesh.triangles[t];
      if (!rows.owns(bodies.dof(l, tri[0], 0))) continue;
      const mortar::ElementMatrix Ke = mortar::element_stiffness(mortar::triangle_vertices(mesh, t), material);
      PetscInt dofs[6];
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 2; ++c) dofs[2 * a + c] = bodies.dof(l, tri[a], c);
      PetscScalar values[36];
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) values[6 * i + j] = Ke(i, j);
      check(MatSetValues(K, 6, dofs, 6, dofs, values, ADD_VALUES), "MatSetValues (element matrix)");
    }
  }
  check(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}
}  // namespace

void assemble(DistributedSystem& s, const mortar::TwoBodies& bodies, const mortar::SceneData& scene) {
  const PetscInt n = bodies.num_dofs();
  s.rows = split_by_nodes(n);
  // A P1 node of these meshes has at most 6 neighbours: 14 columns per row; a row near the
  // end of a rank's range has some of them on the next rank.
  s.K = create_matrix(s.rows, 14);
  check(MatSetOption(s.K, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  add_element_matrices(s.K, s.rows, bodies);

  // loads and coordinates of the owned rows
  check(VecCreateMPI(PETSC_COMM_WORLD, s.rows.local(), n, &s.f), "VecCreateMPI");
  check(VecSetBlockSize(s.f, 2), "VecSetBlockSize");
  check(VecDuplicate(s.f, &s.coordinates), "VecDuplicate");
  for (PetscInt d = s.rows.first; d < s.rows.last; ++d) {
    check(VecSetValue(s.f, d, scene.F[d], INSERT_VALUES), "VecSetValue");
    const int l = d < bodies.offset(1) ? 0 : 1;
    const int node = static_cast<int>((d - bodies.offset(l)) / 2);
    check(VecSetValue(s.coordinates, d, bodies.body(l).mesh.nodes[node][d % 2], INSERT_VALUES), "VecSetValue");
  }
  for (Vec v : {s.f, s.coordinates}) {
    check(VecAssemblyBegin(v), "VecAssemblyBegin");
    check(VecAssemblyEnd(v), "VecAssemblyEnd");
  }

  // Dirichlet: the prescribed values on the diagonal's scale, K stays symmetric
  Vec diagonal;
  check(VecDuplicate(s.f, &diagonal), "VecDuplicate");
  check(MatGetDiagonal(s.K, diagonal), "MatGetDiagonal");
  check(VecMax(diagonal, nullptr, &s.diagonal), "VecMax");
  check(VecDestroy(&diagonal), "VecDestroy");
  s.prescribed.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < scene.dirichlet.dofs.size(); ++k)
    s.prescribed[scene.dirichlet.dofs[k]] = scene.dirichlet.values[k];
  std::vector<PetscInt> rows;
  Vec u_d;
  check(VecDuplicate(s.f, &u_d), "VecDuplicate");
  check(VecSet(u_d, 0.0), "VecSet");
  for (PetscInt d = s.rows.first; d < s.rows.last; ++d)
    if (!std::isnan(s.prescribed[d])) {
      rows.push_back(d);
      check(VecSetValue(u_d, d, s.prescribed[d], INSERT_VALUES), "VecSetValue");
    }
  check(VecAssemblyBegin(u_d), "VecAssemblyBegin");
  check(VecAssemblyEnd(u_d), "VecAssemblyEnd");
  check(MatZeroRowsColumns(s.K, static_cast<PetscInt>(rows.size()), rows.data(), s.diagonal, u_d, s.f),
        "MatZeroRowsColumns (Dirichlet)");
  check(VecDestroy(&u_d), "VecDestroy");

  // the rigid-body modes, for algebraic multigrid (exercise 12)
  MatNullSpace modes;
  check(MatNullSpaceCreateRigidBody(s.coordinates, &modes), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(s.K, modes), "MatSetNearNullSpace");
  check(MatNullSpaceDestroy(&modes), "MatNullSpaceDestroy");
}

}  // namespace chapter09
