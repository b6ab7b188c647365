#include "jobs/report/conversion_report.h"

#include <cmath>
#include <numbers>

#include "src/units.h"

namespace polarform {

void add_conversion_fields(nlohmann::ordered_json& j, const PolarConversion& c, int degree,
                           int control_points, std::size_t knot_count) {
  j["tolerance_mm"] = c.tolerance;
  j["arcs"] = c.arcs.size();
  j["degree"] = degree;
  j["control_points"] = control_points;
  j["knot_count"] = knot_count;
  j["max_radial_error_mm"] = c.max_radial_error;
  j["max_normal_error_mm"] = c.max_normal_error;
  j["worst_angle_deg"] = degrees_in_turn(c.worst_angle);
  j["max_tangent_jump_deg"] = c.max_tangent_jump * kDegreesPerRadian;
  j["base"] = c.base.kind() == ArcKind::quartic ? "quasi-uniform" : "rqb";
  j["alpha"] = c.base.alpha_rule() == AlphaRule::minimax ? "minimax" : "printed";
  j["error_budget"] = {{"function_mm", c.function_error},
                       {"function_exact", c.function_exact},
                       {"synchronization_mm", c.synchronization_error},
                       {"remaining_mm", c.tolerance - c.max_radial_error}};
  j["control_points_steps"] = nlohmann::ordered_json::array();
  for (const ConversionStep& s : c.steps)
    j["control_points_steps"].push_back({{"step", s.name},
                                         {"control_points", s.control_points},
                                         {"max_radial_error_mm", s.max_radial_error}});
  j["arc_list"] = nlohmann::ordered_json::array();
  for (const ArcSummary& a : c.arcs)
    j["arc_list"].push_back({{"start_deg", degrees_in_turn(a.start)},
                             {"sweep_deg", a.sweep * kDegreesPerRadian},
                             {"max_radial_error_mm", a.max_radial_error}});
}

}  // namespace polarform
