// Shared helpers of the fitter tests: rigid motions, Gaussian noise, point clouds sampled from
// known shapes (spheres, cylinders, surfaces of revolution, rotational freeform shapes), and the
// numbers in a message.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

namespace polarform::test {

constexpr double kPi = std::numbers::pi;

// n points of r(θ) about `centre` at random θ in [t0, t1], with normal noise σ per coordinate.
inline Eigen::Matrix2Xd polar_points(const std::function<double(double)>& r, int n, double t0,
                                     double t1, Eigen::Vector2d centre, double sigma,
                                     unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> T(t0, t1);
  std::normal_distribution<double> N(0.0, sigma > 0 ? sigma : 1.0);
  Eigen::Matrix2Xd p(2, n);
  for (int k = 0; k < n; ++k) {
    const double t = T(rng);
    p.col(k) = centre + r(t) * Eigen::Vector2d(std::cos(t), std::sin(t));
    if (sigma > 0) p.col(k) += Eigen::Vector2d(N(rng), N(rng));
  }
  return p;
}

// A measured number for RecordProperty, in 3-digit scientific notation.
inline std::string sci(double x) {
  std::ostringstream o;
  o.precision(3);
  o << std::scientific << x;
  return o.str();
}

// The number written after `key` in a message (NaN when the key is missing).
inline double number_after(const std::string& message, const std::string& key) {
  const std::size_t at = message.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(message.substr(at + key.size()));
}

struct Rigid {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const { return R * x + t; }
  Eigen::Matrix3Xd operator()(const Eigen::Matrix3Xd& x) const { return (R * x).colwise() + t; }
};

inline Rigid random_rigid(unsigned seed, double translation = 100.0) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  const Eigen::Quaterniond q(N(rng), N(rng), N(rng), N(rng));
  std::uniform_real_distribution<double> T(-translation, translation);
  return {q.normalized().toRotationMatrix(), Eigen::Vector3d(T(rng), T(rng), T(rng))};
}

inline void add_noise(Eigen::Matrix3Xd& p, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, sigma);
  for (Eigen::Index k = 0; k < p.size(); ++k) p.data()[k] += N(rng);
}

// Points ρ(φ, θ)·(sinφ cosθ, sinφ sinθ, cosφ) with φ uniform in cos over [phi0, phi1] and θ in
// [theta0, theta1] (area-uniform on the unit sphere).
inline Eigen::Matrix3Xd spherical_cloud(const std::function<double(double, double)>& rho, int n,
                                        double phi0, double phi1, double theta0, double theta1,
                                        unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> C(std::cos(phi1), std::cos(phi0)), T(theta0, theta1);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) {
    const double phi = std::acos(C(rng)), th = T(rng), r = rho(phi, th);
    p.col(k) << r * std::sin(phi) * std::cos(th), r * std::sin(phi) * std::sin(th), r * std::cos(phi);
  }
  return p;
}

// Points r(z, θ)·(cosθ, sinθ) at height z, z uniform in [z0, z1], θ in [theta0, theta1].
inline Eigen::Matrix3Xd cylindrical_cloud(const std::function<double(double, double)>& r, int n,
                                          double z0, double z1, double theta0, double theta1,
                                          unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> Z(z0, z1), T(theta0, theta1);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) {
    const double z = Z(rng), th = T(rng), rr = r(z, th);
    p.col(k) << rr * std::cos(th), rr * std::sin(th), z;
  }
  return p;
}

// Points r(z)·(cosθ_i, sinθ_i) at n_theta equally spaced azimuths θ_i = θ0 + 2πi/n_theta, each at
// the same `heights` random z in [z0, z1]: invariant under rotation by 2π/n_theta about z.
inline Eigen::Matrix3Xd revolution_grid(const std::function<double(double)>& r, int n_theta, int heights,
                                        double z0, double z1, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> Z(z0, z1), T(0.0, 2 * kPi);
  const double t0 = T(rng);
  Eigen::Matrix3Xd p(3, n_theta * heights);
  for (int j = 0; j < heights; ++j) {
    const double z = Z(rng), rr = r(z);
    for (int i = 0; i < n_theta; ++i) {
      const double t = t0 + 2 * kPi * i / n_theta;
      p.col(j * n_theta + i) << rr * std::cos(t), rr * std::sin(t), z;
    }
  }
  return p;
}

}  // namespace polarform::test
