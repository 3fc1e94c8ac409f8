#include "nested_start.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <utility>

#include "common/fem/mesh.hpp"
#include "petsc_check.hpp"

namespace chapter09 {

CoarseAnswer::CoarseAnswer(RowSplit s, Vec displacement, std::vector<double> x_rows, std::vector<double> lambda_rows)
    : split(std::move(s)), u(displacement), x(std::move(x_rows)), lambda(std::move(lambda_rows)) {}

CoarseAnswer::~CoarseAnswer() {
  if (u != nullptr) VecDestroy(&u);
}

namespace {
// One owned node of this level: its first global dof, its body and where it lies in the coarse grid.
struct Target {
  PetscInt dof;
  int body;
  mortar::GridPoint at;
};
}  // namespace

void interpolate_displacement(const CoarseAnswer& coarse, const Part& own, Vec out) {
  PetscInt first = 0, last = 0;
  check(VecGetOwnershipRange(out, &first, &last), "VecGetOwnershipRange");
  std::array<mortar::RectangleSpec, 2> grid;
  std::array<int, 2> row_lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max()}, row_hi{-1, -1};
  std::vector<Target> targets;
  for (int l = 0; l < 2; ++l) {
    grid[l] = mortar::body_rectangle(coarse.split.geometry(), l);
    const mortar::Mesh& mesh = own.bodies.body(l).mesh;
    for (int a = 0; a < mesh.num_nodes(); ++a) {
      const PetscInt dof = own.global(own.bodies.dof(l, a, 0));
      if (dof < first || dof >= last) continue;  // the row above a band is the next rank's
      targets.push_back({dof, l, mortar::locate_in_grid(grid[l], mesh.nodes[a])});
      row_lo[l] = std::min(row_lo[l], targets.back().at.j);
      row_hi[l] = std::max(row_hi[l], targets.back().at.j + 1);
    }
  }
  // The coarse dofs of node rows row_lo..row_hi of each body: one contiguous range each.
  std::vector<PetscInt> wanted;
  std::array<PetscInt, 2> range_start{0, 0}, position{0, 0};
  for (int l = 0; l < 2; ++l) {
    if (row_hi[l] < 0) continue;
    range_start[l] = 2 * coarse.split.node(l, 0, row_lo[l]);
    position[l] = static_cast<PetscInt>(wanted.size());
    const PetscInt end = 2 * (coarse.split.node(l, grid[l].nx, row_hi[l]) + 1);
    for (PetscInt d = range_start[l]; d < end; ++d) wanted.push_back(d);
  }
  IS is;
  Vec local;
  VecScatter scatter;
  check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(wanted.size()), wanted.data(), PETSC_USE_POINTER, &is),
        "ISCreateGeneral");
  check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(wanted.size()), &local), "VecCreateSeq");
  check(VecScatterCreate(coarse.u, is, local, nullptr, &scatter), "VecScatterCreate");
  check(VecScatterBegin(scatter, coarse.u, local, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter, coarse.u, local, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");

  const PetscScalar* c;
  PetscScalar* f;
  check(VecGetArrayRead(local, &c), "VecGetArrayRead");
  check(VecGetArray(out, &f), "VecGetArray");
  for (const Target& t : targets) {
    const int l = t.body;
    const auto at = [&](int i, int j) {
      const PetscInt k = position[l] + 2 * coarse.split.node(l, i, j) - range_start[l];
      return Eigen::Vector2d(c[k], c[k + 1]);
    };
    const int i = t.at.i, j = t.at.j;
    const Eigen::Vector2d u = t.at.interpolate(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    f[t.dof - first] = u.x();
    f[t.dof + 1 - first] = u.y();
  }
  check(VecRestoreArray(out, &f), "VecRestoreArray");
  check(VecRestoreArrayRead(local, &c), "VecRestoreArrayRead");
  VecScatterDestroy(&scatter);
  VecDestroy(&local);
  ISDestroy(&is);
}

std::vector<double> interpolate_multipliers(const CoarseAnswer& coarse, const std::vector<double>& x) {
  std::vector<std::size_t> order(coarse.x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return coarse.x[a] < coarse.x[b]; });
  std::vector<double> out(x.size(), 0.0);
  if (order.empty()) return out;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const auto after = std::lower_bound(order.begin(), order.end(), x[k],
                                        [&](std::size_t a, double v) { return coarse.x[a] < v; });
    if (after == order.begin()) out[k] = coarse.lambda[order.front()];
    else if (after == order.end()) out[k] = coarse.lambda[order.back()];
    else {
      const std::size_t b = *after, a = *(after - 1);
      const double s = (x[k] - coarse.x[a]) / (coarse.x[b] - coarse.x[a]);
      out[k] = (1 - s) * coarse.lambda[a] + s * coarse.lambda[b];
    }
  }
  return out;
}

}  // namespace chapter09
