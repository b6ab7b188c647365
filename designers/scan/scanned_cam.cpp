#include "designers/scan/scanned_cam.h"

#include <cmath>
#include <numbers>

#include "designers/cam/contour_polar_function.h"
#include "src/error.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// R(ψ) of a PolarFunction over 2π, for any ψ.
std::function<double(double)> periodic(const PolarFunction& R) {
  return [R](double psi) {
    const double t = std::fmod(psi - R.start, kTwoPi);
    return R(R.start + (t < 0 ? t + kTwoPi : t));
  };
}

double fitted_radius(const PolarCurveFit& f, double psi) { return f.F(f.base.parameter(psi)); }

Eigen::Matrix2d rotation2(double a) {
  Eigen::Matrix2d r;
  r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return r;
}

PolarCurveFit fit_profile(const Eigen::Matrix2Xd& points, const ScannedCamOptions& o) {
  PolarFitOptions po;
  po.centre = Eigen::Vector2d::Zero();
  po.closure = Closure::closed;
  po.function.size_v = o.contour_ctrl;
  po.function.fairness.mode = FairnessOptions::Mode::gcv;
  po.function.threads = o.threads;
  po.outliers = OutlierPolicy::keep;  // the contour as extracted: its deviations are the inspection
  return fit_polar_curve(points, po);
}

}  // namespace

double rest_height(const Follower& f, double rb) {
  if (f.kind == FollowerKind::FlatFaced) return rb;
  const double rp = f.kind == FollowerKind::Roller ? rb + f.roller_radius : rb;
  return std::sqrt(rp * rp - f.offset * f.offset);
}

double base_radius_from_rest(const Follower& f, double y0) {
  if (f.kind == FollowerKind::FlatFaced) return y0;
  const double rp = std::sqrt(y0 * y0 + f.offset * f.offset);
  return f.kind == FollowerKind::Roller ? rp - f.roller_radius : rp;
}

void ScannedCam::displacement_derivatives(double theta, int d, double* out) const {
  double t = std::fmod(theta, kTwoPi);
  if (t < 0) t += kTwoPi;
  const Eigen::VectorXd v = displacement.height.derivatives(t, d);
  for (int k = 0; k <= d; ++k) out[k] = v[k];
  out[0] -= rest_height;
}

double ScannedCam::radius(double psi) const { return fitted_radius(fit, psi); }

ScannedCam analyse_scanned_cam(const Eigen::Matrix3Xd& points, const ScannedCamOptions& o) {
  ScannedCam r;
  r.follower = o.follower;
  r.rotation = o.rotation;
  r.profile = extract_cam_profile(points, o.profile);
  r.contour = r.profile.contour;
  r.cam_frame = r.profile.plane;
  r.fit = fit_profile(r.contour, o);
  if (o.nominal) {
    const auto nominal = periodic(cam_polar_function(*o.nominal));
    const PolarCurveFit& first = r.fit;
    r.alignment = align_phase([&](double psi) { return fitted_radius(first, psi); }, nominal, true);
    r.mirrored = r.alignment->mirrored;
    // Scan coordinates q = M·Rot(δ)·c for cam-frame points c (M mirrors y when the scan is seen
    // from the other face).
    Eigen::Matrix3d to_scan = Eigen::Matrix3d::Identity();
    if (r.mirrored) {
      r.contour.row(1) *= -1.0;
      to_scan.diagonal() << 1.0, -1.0, -1.0;
    }
    r.contour = rotation2(-r.alignment->phase) * r.contour;
    to_scan.topLeftCorner<2, 2>() = to_scan.topLeftCorner<2, 2>() * rotation2(r.alignment->phase);
    r.cam_frame.axes = r.profile.plane.axes * to_scan;
    r.fit = fit_profile(r.contour, o);
  }
  const FitReport& rep = r.fit.report;
  const double n = static_cast<double>(rep.signed_distance.size());
  r.contour_noise =
      std::sqrt(rep.signed_distance.squaredNorm() / std::max(1.0, n - std::max(0.0, rep.dof)));
  r.samples = invert_follower(r.fit, r.contour, o.follower, o.rotation);
  DisplacementFitOptions d = o.displacement;
  d.threads = o.threads;
  r.displacement = fit_displacement(r.samples, d);
  double lowest = INFINITY;
  for (int i = 0; i < 7200; ++i)
    lowest = std::min(lowest, r.displacement.height(kTwoPi * i / 7200));
  r.measured_rest_height = lowest;
  r.base_radius = base_radius_from_rest(o.follower, lowest);
  r.rest_height = o.nominal ? rest_height(o.nominal->follower(), o.nominal->base_radius()) : lowest;
  return r;
}

}  // namespace polarform
