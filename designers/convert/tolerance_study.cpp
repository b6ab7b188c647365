#include "designers/convert/tolerance_study.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "designers/convert/degree_limited.h"
#include "designers/convert/polar_conversion.h"
#include "src/base/angle_deviation.h"
#include "src/error.h"
#include "src/units.h"

namespace polarform {

std::vector<double> log_tolerances(double loosest, double tightest, int per_decade) {
  if (!(tightest > 0 && loosest >= tightest))
    throw InputError("tolerance range: expected LOOSEST:TIGHTEST with LOOSEST >= TIGHTEST > 0 mm");
  if (per_decade < 1) throw InputError("tolerance range: steps per decade must be >= 1");
  const double decades = std::log10(loosest / tightest);
  const int steps = static_cast<int>(std::lround(decades * per_decade));
  // Rounded to 12 significant digits so that decades land on 1e-4, not 9.999999999999996e-05.
  const auto round12 = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", x);
    return std::strtod(text, nullptr);
  };
  std::vector<double> out;
  for (int k = 0; k <= steps; ++k)
    out.push_back(steps == 0 ? loosest
                             : round12(loosest * std::pow(tightest / loosest, double(k) / steps)));
  return out;
}

namespace {

StudyMethodResult base_method(const PolarFunction& R, double tol, ArcKind kind) {
  ConversionOptions options;
  options.tolerance = tol;
  options.base = kind;
  // The base arcs compared as they build C = F·B (the product step, before any knot removal).
  options.compaction = Compaction::none;
  const PolarConversion c = convert_polar_function(R, options);
  return {static_cast<int>(c.arcs.size()), 0, c.curve.degree(), c.curve.size(), c.max_radial_error};
}

}  // namespace

std::vector<StudyRow> tolerance_study(const PolarFunction& R, const std::vector<double>& tolerances,
                                      const std::function<void(double)>& progress) {
  std::vector<StudyRow> rows;
  for (std::size_t k = 0; k < tolerances.size(); ++k) {
    const double tol = tolerances[k];
    StudyRow row;
    row.tolerance = tol;
    row.quartic = base_method(R, tol, ArcKind::quartic);
    row.rqb = base_method(R, tol, ArcKind::rqb);
    const LimitedCurve cubic = interpolate_polar_curve(R, 3, tol);
    // A closed interpolant has as many distinct control values as points (3 repeat at the seam).
    row.cubic = {0, R.closed() ? cubic.control_points - 3 : cubic.control_points, 3,
                 cubic.control_points, cubic.max_radial_error};
    rows.push_back(row);
    if (progress) progress(static_cast<double>(k + 1) / tolerances.size());
  }
  return rows;
}

std::vector<DeviationRow> angle_deviation_study(int count) {
  if (count < 2) throw InputError("angle deviation study: at least 2 arc angles");
  std::vector<DeviationRow> out;
  for (int k = 0; k < count; ++k) {
    const double angle =
        2 * kRadiansPerDegree * std::pow(90.0, static_cast<double>(k) / (count - 1));
    DeviationRow row;
    row.arc_angle = angle;
    row.rqb = max_angle_deviation(ArcKind::rqb, angle / 2);
    row.quartic_minimax = max_angle_deviation(ArcKind::quartic, angle / 2, AlphaRule::minimax);
    row.quartic_printed = max_angle_deviation(ArcKind::quartic, angle / 2, AlphaRule::printed);
    out.push_back(row);
  }
  return out;
}

}  // namespace polarform
