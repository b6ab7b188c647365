#include "tests/support/designers/synthetic_scans.h"

#include <cmath>
#include <numbers>
#include <random>

#include "designers/cam/contour_polar_function.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

void add_noise(Eigen::Matrix3Xd& p, double sigma, std::mt19937& rng) {
  if (!(sigma > 0.0)) return;
  std::normal_distribution<double> N(0.0, sigma);
  for (Eigen::Index k = 0; k < p.size(); ++k) p.data()[k] += N(rng);
}

Eigen::Vector3d on_sphere(double rho, double phi, double theta) {
  return rho * Eigen::Vector3d(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                               std::cos(phi));
}

// A point of the contour at cam angle θ with its outward unit normal (oriented away from the
// centre: the contour is star-shaped about it).
void contour_point(const PlateCam& cam, double theta, Eigen::Vector2d& point,
                   Eigen::Vector2d& normal) {
  Eigen::Vector2d c[2];
  cam.contour(theta, 1, c);
  point = c[0];
  normal = Eigen::Vector2d(-c[1].y(), c[1].x()).normalized();
  if (normal.dot(point) < 0) normal = -normal;
}

// The cam-frame point turned by the phase and moved to the centre.
Eigen::Vector2d place(const Eigen::Vector2d& x, const CamScanSetup& s) {
  const double c = std::cos(s.phase), sn = std::sin(s.phase);
  return s.centre + Eigen::Vector2d(c * x.x() - sn * x.y(), sn * x.x() + c * x.y());
}

}  // namespace

Eigen::Matrix3Xd RigidMotion::operator()(const Eigen::Matrix3Xd& x) const {
  return (rotation * x).colwise() + translation;
}

double vase_radius(double z, double theta) {
  return 24.0 - 5.0 * std::sin(kPi * z / 80.0) + 0.8 * std::cos(2.0 * theta) * z / 80.0;
}

Eigen::Matrix3Xd vase_cloud(int n, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> Z(0.0, 80.0), T(0.0, 2 * kPi);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) {
    const double z = Z(rng), theta = T(rng), r = vase_radius(z, theta);
    p.col(k) << r * std::cos(theta), r * std::sin(theta), z;
  }
  add_noise(p, sigma, rng);
  return p;
}

Eigen::Matrix3Xd sphere_cloud(int n, double radius, const Eigen::Vector3d& centre, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> C(-1.0, 1.0), T(0.0, 2 * kPi);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) p.col(k) = centre + on_sphere(radius, std::acos(C(rng)), T(rng));
  return p;
}

Eigen::Matrix3Xd cone_cloud(int n, double r0, double slope, double height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> Z(0.0, height), T(0.0, 2 * kPi);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) {
    const double z = Z(rng), theta = T(rng), r = r0 + slope * z;
    p.col(k) << r * std::cos(theta), r * std::sin(theta), z;
  }
  return p;
}

Eigen::Matrix3Xd cam_profile_scan(const PlateCam& cam, const CamScanSetup& s) {
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> T(0.0, 2 * kPi);
  std::normal_distribution<double> N(0.0, s.sigma > 0 ? s.sigma : 1.0);
  const auto noise = [&] { return s.sigma > 0 ? N(rng) : 0.0; };
  Eigen::Matrix3Xd p = Eigen::Matrix3Xd::Zero(3, s.contour_points + s.bore_points);
  for (int k = 0; k < s.contour_points; ++k) {
    Eigen::Vector2d c, n;
    contour_point(cam, T(rng), c, n);
    p.col(k).head<2>() = place(c + noise() * n, s);
  }
  for (int k = 0; k < s.bore_points; ++k) {
    const double a = T(rng), r = s.bore_radius + noise();
    p.col(s.contour_points + k).head<2>() =
        place(Eigen::Vector2d(r * std::cos(a), r * std::sin(a)), s);
  }
  return p;
}

Eigen::Matrix3Xd cam_solid_scan(const PlateCam& cam, const CamScanSetup& s, double thickness,
                                int face_points, const RigidMotion& placement) {
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> T(0.0, 2 * kPi), U(0.0, 1.0),
      H(-thickness / 2, thickness / 2);
  const PolarFunction R = cam_polar_function(cam);
  const int n = 2 * face_points + s.contour_points + s.bore_points;
  Eigen::Matrix3Xd p(3, n);
  int k = 0;
  for (int face = 0; face < 2; ++face)
    for (int i = 0; i < face_points; ++i, ++k) {
      // Area-uniform between the bore and the contour along each ray.
      const double psi = R.start + (R.end - R.start) * U(rng);
      const double r0 = s.bore_radius, r1 = R(psi);
      const double r = std::sqrt(r0 * r0 + U(rng) * (r1 * r1 - r0 * r0));
      p.col(k) << r * std::cos(psi), r * std::sin(psi), face == 0 ? -thickness / 2 : thickness / 2;
    }
  for (int i = 0; i < s.contour_points; ++i, ++k) {
    Eigen::Vector2d c, normal;
    contour_point(cam, T(rng), c, normal);
    p.col(k) << c.x(), c.y(), H(rng);
  }
  for (int i = 0; i < s.bore_points; ++i, ++k) {
    const double a = T(rng);
    p.col(k) << s.bore_radius * std::cos(a), s.bore_radius * std::sin(a), H(rng);
  }
  for (Eigen::Index c = 0; c < p.cols(); ++c) {
    const Eigen::Vector2d xy = place(p.col(c).head<2>(), s);
    p.col(c).head<2>() = xy;
  }
  add_noise(p, s.sigma, rng);
  return placement(p);
}

}  // namespace polarform
