#include "src/fit/profile_fairing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/fit/curve_distance.h"
#include "src/fit/error_stats.h"
#include "src/nurbs/knots.h"

namespace polarform {

std::string fairing_method_name(FairingMethod method) {
  return method == FairingMethod::farin ? "farin" : "kjellander";
}

double fairing_tolerance(const ProfileFairingOptions& options, double rms) {
  const double t = options.tolerance > 0 ? options.tolerance : 3.0 * rms;
  if (!(t > 0))
    throw InputError(
        "fairing: the fit has no residual to estimate a tolerance from; give --fair-tol");
  return t;
}

ProfileFairing fair_polar_curve(PolarCurveFit& fit, const Eigen::Matrix2Xd& points,
                                const ProfileFairingOptions& options) {
  ProfileFairing r;
  r.method = options.method;
  r.tolerance = fairing_tolerance(options, fit.report.error.rms);
  FairingOptions o;
  o.tolerance = r.tolerance;
  o.max_passes = options.max_passes;
  const BSpline& F0 = fit.F.spline();
  o.fixed_end_points = fit.closed ? F0.degree() : 0;
  r.max_jump_before = max_top_derivative_jump(F0);
  BSpline F1 = F0;
  if (options.method == FairingMethod::farin) {
    CurveFairing f = farin_fair(F0, o);
    F1 = std::move(f.spline);
    r.steps = std::move(f.steps);
  } else {
    CurveFairing k = kjellander_fair_spline(F0, o);
    F1 = std::move(k.spline);
    r.steps = std::move(k.steps);
  }
  r.max_jump_after = max_top_derivative_jump(F1);
  const NurbsCurve2d before = fit.curve;
  fit.F = BSplineFunction(F1);
  fit.curve = polar_product_curve(fit.F, fit.base, fit.centre);
  for (int k = 0; k <= 20000; ++k) {
    const double u = before.front() + (before.back() - before.front()) * k / 20000;
    r.measured_deviation =
        std::max(r.measured_deviation, (fit.curve.point(u) - before.point(u)).norm());
  }
  for (const FairingStep& s : r.steps) {
    const Eigen::Vector2d q = fit.curve.point(s.u) - fit.centre;
    r.step_angle_deg.push_back(std::atan2(q.y(), q.x()) * 180 / std::numbers::pi);
  }
  // The error of the faired curve: true distances of every point, signed outward.
  const CurveDistance<2> distance(fit.curve, fit.closed);
  Eigen::VectorXd d(points.cols());
  std::vector<char> left_out(static_cast<std::size_t>(points.cols()), 0);
  for (const Eigen::Index k : fit.report.outliers.points) left_out[static_cast<std::size_t>(k)] = 1;
  std::vector<double> kept;
  for (Eigen::Index k = 0; k < points.cols(); ++k) {
    const CurveDistance<2>::Foot f = distance.project(points.col(k));
    const bool outside =
        (points.col(k) - fit.centre).norm() >= (fit.curve.point(f.u) - fit.centre).norm();
    d[k] = outside ? f.distance : -f.distance;
    if (!left_out[static_cast<std::size_t>(k)]) kept.push_back(d[k]);
  }
  fit.report.signed_distance = d;
  fit.report.error = error_stats(
      Eigen::Map<const Eigen::VectorXd>(kept.data(), static_cast<Eigen::Index>(kept.size())));
  return r;
}

}  // namespace polarform
