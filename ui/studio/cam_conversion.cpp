#include "ui/studio/cam_conversion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/cam/contour_polar_function.h"
#include "designers/convert/conversion_error.h"
#include "jobs/cam/cam_job.h"
#include "src/units.h"

namespace polarform::studio {
namespace {

constexpr int kErrorSamples = 720;

}  // namespace

CamConversion convert_cam(const CamResults& r, const CamProject& project) {
  CamConversion c;
  c.options = project.conversion;
  PolarFunction f;
  if (r.plate) {
    f = cam_polar_function(*r.plate, CamCurve::Contour);
    c.conversion = convert_polar_function(f, project.conversion);
  } else {
    CamJobOptions options;
    options.with_limited = false;
    CamJobResult job = run_cam_job(project, options);
    f = std::move(job.profile_function);
    c.conversion = std::move(job.conversion);
  }
  c.summary = summarize(c.conversion);
  const NurbsCurve2d& curve = c.conversion.curve;
  const BaseCircle& base = c.conversion.base;
  // The measured error along the whole curve, at equal parameter steps.
  std::vector<std::pair<double, double>> samples;
  samples.reserve(kErrorSamples + 1);
  for (int i = 0; i <= kErrorSamples; ++i) {
    const double u = curve.front() + (curve.back() - curve.front()) * i / kErrorSamples;
    double psi = 0.0;
    const double e = radial_error_at(curve, f, u, base.angle(u), &psi);
    samples.emplace_back(degrees_in_turn(psi), e * 1e3);
  }
  std::sort(samples.begin(), samples.end());
  for (const auto& [angle, error] : samples) {
    c.error_angle_deg.push_back(angle);
    c.error_um.push_back(error);
  }
  for (std::size_t k = 1; k < c.conversion.arcs.size(); ++k)
    c.junctions_deg.push_back(degrees_in_turn(c.conversion.arcs[k].start));
  return c;
}

}  // namespace polarform::studio
