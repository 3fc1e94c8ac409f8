// A finite-body reference for the Hertz scene, computed by this program: the same bodies,
// supports, materials, R and delta as the run, on meshes graded towards the two edges of the
// contact zone (in x) and towards Gamma_c (in y), matching traces, integral matching, active
// set. The levels' discretization error is measured against it; half-space Hertz is compared
// with it, not with the levels, and their distance is the model error.
//
// The mesh is a tensor product of graded_nodes (common/mesh). In x the cell size is h_edge
// in a window around each edge of the contact zone, grows by a factor 1 + growth per cell
// away from it, and is capped at h_zone inside the zone and at h_max outside; in y it is
// h_edge on Gamma_c and grows the same way up to h_max. The windows come from a chain of
// cheaper solves, each locating the edges to within its own h_edge for the next. A second
// reference with every cell twice as long gives the reference's own error: their difference.
#pragma once

#include <memory>
#include <vector>

#include "study.hpp"

namespace chapter05 {

struct ReferenceGrading {
  double h_edge = 0;   // cell size at the edges of the contact zone and along Gamma_c [m]
  double growth = 0;   // cells grow by a factor 1 + growth away from them [-]
  double h_zone = 0;   // largest cell along Gamma_c inside the contact zone [m]
  double h_max = 0;    // largest cell anywhere [m]
  // every cell twice as long: the size function doubles, h_edge + growth d included
  ReferenceGrading doubled() const { return {2 * h_edge, 2 * growth, 2 * h_zone, 2 * h_max}; }
};

// The grading of the reference, tied to the finest level's h1 so that
// the reference stays finer than every level when --n0 or --levels change.
ReferenceGrading reference_grading(const Options& o);

// Where the contact zone ends on each side: the edge lies in [outer, inner] (both in x).
struct ZoneEdges {
  double left_outer = 0, left_inner = 0, right_inner = 0, right_outer = 0;
};

// A reference value and its estimated error: the relative change from the coarse reference.
struct Estimate {
  double value = 0, change = 0;
};

struct HertzReference {
  std::unique_ptr<UnilateralLevel> coarse, fine;  // fine is the reference; both null without contact
  ReferenceGrading grading;                       // of fine
  int passes = 0;      // solves that located the edges before the two references
  double time_s = 0;   // wall time of all of them, limits included
  mortar::InterfaceCurve pressure;  // of fine (all zero without contact)
  mortar::ContactZone zone;         // of fine
  Estimate force, half_width, peak;  // total force [N/m], a [m], peak_pressure [Pa]
  double pressure_change = 0;  // ||p_fine - p_coarse|| / ||p_fine||, L2(Gamma_c)
  // The model error: the reference against half-space Hertz at the reference's force.
  double model_pressure = 0;    // ||p_ref - p_Hertz|| / ||p_Hertz||, L2(Gamma_c)
  double model_peak = 0;        // (peak_ref - p0) / p0, signed
  double model_half_width = 0;  // (a_ref - a) / a, signed
};

HertzReference make_hertz_reference(const Options& o, const mortar::ExactContact& exact,
                                    const ReferenceGrading& grading);

// How far the reference's contact edges lie outside the level's discrete bracket (outermost
// node in contact, first neighbour out of contact), in lengths of that bracket's element; the
// larger of the two sides, 0 when both are bracketed. The reference's edges are themselves
// brackets (of its own, much shorter, element): the distance is between the two intervals.
// h is the level's element length, the unit where a bracket has none (a zone that reaches an
// end of Gamma_c); when only one of the two has contact, the whole zone that the other misses
// counts: its width over h.
double edge_offset_in_elements(const mortar::ContactZone& level, const mortar::ContactZone& reference, double h);

// One solve on graded meshes whose h_edge windows cover the given edges.
UnilateralLevel solve_graded(const Options& o, const mortar::ExactContact& exact,
                             const ZoneEdges& edges, const ReferenceGrading& g);

// ||p - q|| / ||q|| in L2(Gamma_c) for two P1 curves on different points: exact, on the union
// of their breakpoints.
double relative_l2_distance(const mortar::InterfaceCurve& p, const mortar::InterfaceCurve& q);
// The same with the error integrated over (lo, hi) only (the norm of q stays the whole of
// Gamma_c): how much of the error lies there.
double relative_l2_distance_on(const mortar::InterfaceCurve& p, const mortar::InterfaceCurve& q,
                               double lo, double hi);

}  // namespace chapter05
