#include "jobs/fit/profile_interrogation.h"

#include <cmath>

#include "export/csv_writer.h"
#include "src/nurbs/curve_interrogation.h"
#include "src/units.h"

namespace polarform {

namespace {

// The polar angle of the curve point at u about the fit's centre, in [0°, 360°).
double angle_at(const PolarCurveFit& fit, double u) {
  const Eigen::Vector2d d = fit.curve.point(u) - fit.centre;
  const double a = std::atan2(d.y(), d.x()) * kDegreesPerRadian;
  return a < 0 ? a + 360 : a;
}

}  // namespace

ProfileInterrogation interrogate_profile(const PolarCurveFit& fit, int samples) {
  const NurbsCurve2d& c = fit.curve;
  ProfileInterrogation out;
  out.order = c.degree();
  for (int i = 0; i <= samples; ++i) {
    const double u = c.front() + (c.back() - c.front()) * i / samples;
    const Eigen::Vector2d p = c.point(u);
    out.u.push_back(u);
    out.x.push_back(p.x());
    out.y.push_back(p.y());
    out.angle_deg.push_back(angle_at(fit, u));
    out.curvature.push_back(signed_curvature(c, u));
    out.curvature_derivative.push_back(curvature_derivative(c, u));
  }
  for (const double u : inflections(c)) out.inflections.push_back({u, angle_at(fit, u), 0.0});
  for (const KnotJump& j : derivative_jumps(c, c.degree()))
    out.derivative_jumps.push_back({j.u, angle_at(fit, j.u), j.jump});
  return out;
}

std::string interrogation_csv(const ProfileInterrogation& q) {
  CsvWriter csv({"u", "x [mm]", "y [mm]", "polar angle [deg]", "kappa [1/mm]", "dkappa/du [1/mm]"});
  for (std::size_t i = 0; i < q.u.size(); ++i)
    csv.row({q.u[i], q.x[i], q.y[i], q.angle_deg[i], q.curvature[i], q.curvature_derivative[i]});
  return csv.str();
}

nlohmann::ordered_json interrogation_json(const ProfileInterrogation& q) {
  nlohmann::ordered_json j = {{"inflections_deg", nlohmann::ordered_json::array()},
                              {"derivative_order", q.order},
                              {"max_derivative_jump", 0.0},
                              {"max_derivative_jump_at_deg", nullptr}};
  for (const ProfileInterrogation::Place& p : q.inflections)
    j["inflections_deg"].push_back(p.angle_deg);
  for (const ProfileInterrogation::Place& p : q.derivative_jumps)
    if (p.value > j["max_derivative_jump"].get<double>()) {
      j["max_derivative_jump"] = p.value;
      j["max_derivative_jump_at_deg"] = p.angle_deg;
    }
  return j;
}

nlohmann::ordered_json fairing_json(const ProfileFairing& f) {
  nlohmann::ordered_json knots = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < f.steps.size(); ++k)
    knots.push_back({{"u", f.steps[k].u},
                     {"u_deg", f.step_angle_deg[k]},
                     {"jump_before", f.steps[k].jump_before},
                     {"jump_after", f.steps[k].jump_after},
                     {"bound_mm", f.steps[k].bound}});
  return {{"method", fairing_method_name(f.method)},
          {"tolerance_mm", f.tolerance},
          {"passes", f.steps.size()},
          {"knots_faired", knots},
          {"max_jump_before", f.max_jump_before},
          {"max_jump_after", f.max_jump_after},
          {"measured_deviation_mm", f.measured_deviation}};
}

}  // namespace polarform
