#include "ui/studio/vessel_results.h"

#include <numbers>

#include "src/units.h"
#include "ui/studio/guarded.h"

namespace polarform::studio {
namespace {

XYSeries radius_series(const PolarFunction& f) {
  XYSeries s;
  for (int i = 0; i <= 720; ++i) {
    const double theta = f.start + (f.end - f.start) * i / 720;
    s.x.push_back(theta * kDegreesPerRadian);
    s.y.push_back(f(theta));
  }
  return s;
}

XYSeries curvature_series(const std::vector<CurvatureSample>& samples) {
  XYSeries s;
  for (const CurvatureSample& c : samples) {
    s.x.push_back(c.theta * kDegreesPerRadian);
    s.y.push_back(c.kappa);
  }
  return s;
}

void stress_series(const StressProfile& p, XYSeries& meridional, XYSeries& hoop) {
  for (const StressSample& s : p.samples) {
    meridional.x.push_back(s.s);
    meridional.y.push_back(s.meridional_stress);
    hoop.x.push_back(s.s);
    hoop.y.push_back(s.hoop_stress);
  }
}

}  // namespace

VesselResults compute_vessel_results(const VesselProject& project) {
  VesselResults r;
  r.project = project;
  r.solution = solve_vessel(to_design(project));
  const VesselSolution& s = r.solution;
  r.radius = radius_series(s.profile);
  r.kappa = curvature_series(s.curvature);
  for (const TargetResidual& t : s.synthesis.targets) {
    r.targets.x.push_back(t.theta * kDegreesPerRadian);
    r.targets.y.push_back(t.target);
    r.achieved.x.push_back(t.theta * kDegreesPerRadian);
    r.achieved.y.push_back(t.achieved);
    r.residuals.x.push_back(t.theta * kDegreesPerRadian);
    r.residuals.y.push_back(t.residual());
  }
  stress_series(s.stresses, r.meridional, r.hoop);
  if (s.preset) {
    r.preset_radius = radius_series(s.preset->shape.profile);
    r.preset_kappa = curvature_series(s.preset->curvature);
    r.preset_meridional.emplace();
    r.preset_hoop.emplace();
    stress_series(s.preset->stresses, *r.preset_meridional, *r.preset_hoop);
  }
  try {
    ConversionOptions options;
    options.tolerance = project.tolerance;
    const PolarConversion conversion = convert_polar_function(s.profile, options);
    r.conversion = summarize(conversion);
    r.surfaces = vessel_surfaces(conversion.curve, project.design.length);
  } catch (...) {
    r.conversion_error = failure_text("conversion", std::current_exception());
  }
  return r;
}

}  // namespace polarform::studio
