#include "hertz_report.hpp"

#include <cmath>
#include <cstdio>

#include "hertz.hpp"

namespace chapter05 {

namespace {
double finest(const mortar::ConvergenceTable& table, const std::string& column) { return table.column(column).back(); }
}  // namespace

void add_hertz_results(mortar::JsonObject& results, const Options& o, const mortar::ConvergenceTable& table,
                       const UnilateralLevel& f, const HertzReference& ref) {
  const Hertz h = hertz_for(o, f);
  results.set("reference", "finite bodies on graded meshes (hertz_reference)")
      .set("peak_pressure_pa", finest(table, "peak_pressure"))
      // the two numbers: the finest level against the reference, the reference against Hertz
      .set("hertz_discretization_error", finest(table, "err_pressure"))
      .set("hertz_model_error", ref.model_pressure)
      .set("discretization_peak_pressure_rel_error", finest(table, "err_peak_pressure"))
      .set("discretization_half_width_rel_error", finest(table, "err_half_width"))
      .set("discretization_total_force_rel_error", finest(table, "err_total_force"))
      .set("hertz_model_peak_pressure_rel_error", ref.model_peak)
      .set("hertz_model_half_width_rel_error", ref.model_half_width)
      // the reference and its own error: the change from cells twice as long
      .set("reference_rel_error_estimate", ref.pressure_change)
      .set("reference_dofs", ref.fine ? ref.fine->bodies.num_dofs() : 0)
      .set("reference_h_edge_m", ref.grading.h_edge)
      .set("reference_time_s", ref.time_s)
      .set("reference_total_force", ref.force.value)
      .set("reference_total_force_rel_change", ref.force.change)
      .set("reference_half_width_m", ref.half_width.value)
      .set("reference_half_width_rel_change", ref.half_width.change)
      .set("reference_peak_pressure_pa", ref.peak.value)
      .set("reference_peak_pressure_rel_change", ref.peak.change)
      // where the discrete contact set ends against the reference's edges, in elements
      .set("reference_edge_offset_elements", finest(table, "edge_offset_elements"))
      .set("reference_edges_within_one_element", finest(table, "edge_offset_elements") <= 1.0)
      // the finest level against Hertz directly: model and discretization error together
      .set("hertz_half_width", h.half_width())
      .set("hertz_peak_pressure", h.peak_pressure())
      .set("hertz_half_width_rel_error", std::fabs(finest(table, "hertz_distance_half_width")))
      .set("hertz_peak_pressure_rel_error", std::fabs(finest(table, "hertz_distance_peak")));
}

void print_hertz_errors(const Options& o, const mortar::ConvergenceTable& table,
                        const UnilateralLevel& f, const HertzReference& ref) {
  if (!ref.fine) {
    // No reference: its graded meshes saw no contact. Say what the levels saw: "do not touch"
    // only where neither a multiplier nor the pointwise gap says otherwise (a zone narrower
    // than an element can show one active node, or none and a penetration: the warning above).
    if (!f.zone.empty)
      std::printf("note: the finest level has %d node%s in contact (total force %.3g N/m), but the reference "
                  "(integral matching on graded meshes) found none: the zone is narrower than an element, where "
                  "values at nodes and averages over elements disagree; the Hertz errors are 0 by convention and "
                  "their rates are undefined (null)\n",
                  f.zone.active_nodes, f.zone.active_nodes == 1 ? "" : "s", f.total_force);
    else
      std::printf("note: %s (total force 0): the Hertz errors are 0 by convention and their rates are undefined "
                  "(null)\n",
                  f.penetrates() ? "no multiplier is active, on the levels or on the reference's meshes"
                                 : "the bodies do not touch");
    return;
  }
  std::printf("finite-body reference: %d dofs graded to %.2g m at the contact edges, total force "
              "%.6g N/m, half-width %.5f m, peak pressure %.5g Pa; its own error, from cells twice "
              "as long: %.2g (pressure, L2), %.1e (force), %.1e (half-width), %.1e (peak); %.1f s\n",
              ref.fine->bodies.num_dofs(), ref.grading.h_edge, ref.force.value, ref.half_width.value,
              ref.peak.value, ref.pressure_change, ref.force.change, ref.half_width.change,
              ref.peak.change, ref.time_s);
  std::printf("discretization error (finest level against the reference): pressure %.2f%% (L2), "
              "peak %.2f%%, half-width %.2f%%, force %.3f%%\n",
              100 * finest(table, "err_pressure"), 100 * finest(table, "err_peak_pressure"),
              100 * finest(table, "err_half_width"), 100 * finest(table, "err_total_force"));
  std::printf("model error (reference against half-space Hertz at its force): pressure %.2f%% (L2), "
              "peak %+.2f%%, half-width %+.2f%%\n",
              100 * ref.model_pressure, 100 * ref.model_peak, 100 * ref.model_half_width);
  const Hertz h = hertz_for(o, f);
  if (h.half_width() > o.L / 4)
    std::printf("note: Hertz's half-width %.3g m is more than L/4: the half-space theory does not "
                "describe these bodies, and the model error measures that\n", h.half_width());
}

}  // namespace chapter05
