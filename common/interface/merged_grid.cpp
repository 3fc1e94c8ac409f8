#include "common/interface/merged_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/timing/profile.hpp"

namespace mortar {

MergedGrid merge_traces(const InterfaceTrace& t1, const InterfaceTrace& t2, double rel_tol) {
  const ProfilePhase phase("interface and constraints");
  const double L = t1.length();
  if (std::fabs(t1.x.front() - t2.x.front()) > rel_tol * L ||
      std::fabs(t1.x.back() - t2.x.back()) > rel_tol * L)
    throw std::invalid_argument(
        "merge_traces: the traces must share their end points a1, a2 (paper section 3); got [" +
        std::to_string(t1.x.front()) + ", " + std::to_string(t1.x.back()) + "] and [" +
        std::to_string(t2.x.front()) + ", " + std::to_string(t2.x.back()) + "]");

  // All breakpoints tagged by their side, in increasing x.
  std::vector<std::pair<double, int>> all;
  for (double p : t1.x) all.emplace_back(p, 1);
  for (double p : t2.x) all.emplace_back(p, 2);
  std::sort(all.begin(), all.end());

  // Cluster points closer than tol to the cluster's first point; a cluster is represented by
  // its side-1 node when it has one, so D is integrated on side 1's own geometry.
  MergedGrid grid;
  const double tol = rel_tol * L;
  double cluster_start = 0;
  bool has_side1 = false;
  for (const auto& [p, side] : all) {
    if (grid.breakpoints.empty() || p - cluster_start > tol) {
      grid.breakpoints.push_back(p);
      cluster_start = p;
      has_side1 = side == 1;
    } else if (side == 1 && !has_side1) {
      grid.breakpoints.back() = p;
      has_side1 = true;
    }
  }

  for (std::size_t s = 0; s + 1 < grid.breakpoints.size(); ++s) {
    MergedSegment seg;
    seg.a = grid.breakpoints[s];
    seg.b = grid.breakpoints[s + 1];
    const double mid = 0.5 * (seg.a + seg.b);
    seg.element1 = t1.element_containing(mid);
    seg.element2 = t2.element_containing(mid);
    grid.segments.push_back(seg);
  }
  return grid;
}

}  // namespace mortar
