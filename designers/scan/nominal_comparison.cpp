#include "designers/scan/nominal_comparison.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "designers/cam/contour_polar_function.h"
#include "designers/scan/profile_foot.h"
#include "src/error.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

ErrorStats stats(const std::vector<double>& v) {
  return error_stats(
      Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
}

}  // namespace

NominalComparison compare_to_nominal(const ScannedCam& scan, const PlateCam& nominal, int samples,
                                     double phase) {
  if (samples < 16)
    throw InputError("nominal comparison: " + std::to_string(samples) +
                     " samples, expected at least 16");
  NominalComparison c;
  const ProfileFeet feet(scan.fit);
  const double turn = nominal.sense() * phase;  // the nominal's frame from the scan's
  const Eigen::Matrix2d to_scan = Eigen::Rotation2Dd(-turn).toRotationMatrix();
  for (int i = 0; i < samples; ++i) {
    const double theta = kTwoPi * i / samples;
    Eigen::Vector2d C;
    nominal.contour(theta - phase, 0, &C);
    C = to_scan * C;
    const double psi = std::atan2(C.y(), C.x());
    const double radial = scan.radius(psi) - C.norm();
    c.theta.push_back(theta);
    c.radial.push_back(radial);
    c.normal.push_back(-feet(C).distance);  // C outside the fitted profile: material missing
    double s[4], nom[4];
    scan.displacement_derivatives(theta, 3, s);
    nominal.program().derivatives(theta - phase, 3, nom);
    for (int k = 0; k < 4; ++k) {
      c.svaj_difference[static_cast<std::size_t>(k)].push_back(s[k] - nom[k]);
      c.nominal_svaj[static_cast<std::size_t>(k)].push_back(nom[k]);
    }
  }
  c.radial_stats = stats(c.radial);
  c.normal_stats = stats(c.normal);
  for (std::size_t k = 0; k < 4; ++k) c.svaj_stats[k] = stats(c.svaj_difference[k]);
  const PolarFunction R = cam_polar_function(nominal);
  c.point_radial.resize(scan.contour.cols());
  c.point_normal.resize(scan.contour.cols());
  for (Eigen::Index k = 0; k < scan.contour.cols(); ++k) {
    const Eigen::Vector2d q = scan.contour.col(k);
    double t = std::fmod(std::atan2(q.y(), q.x()) + turn - R.start, kTwoPi);
    if (t < 0) t += kTwoPi;
    double r[2];
    R.derivatives(R.start + t, 1, r);
    c.point_radial[k] = q.norm() - r[0];
    // The radial gap projected on the normal of R(ψ): cos of the ray–normal angle is R/√(R²+R'²).
    c.point_normal[k] = c.point_radial[k] * r[0] / std::hypot(r[0], r[1]);
  }
  c.point_stats = error_stats(c.point_radial);
  c.point_normal_stats = error_stats(c.point_normal);
  return c;
}

}  // namespace polarform
