#include "src/fit/orthogonal_coordinates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/parallel.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// atan2 mapped to [0, 2π), the quadrant cases of Bae 2002, eq. (2.2).
double azimuth(double x, double y) {
  const double t = std::atan2(y, x);
  return t < 0.0 ? t + kTwoPi : t;
}

[[noreturn]] void degenerate(Eigen::Index k, const char* what) {
  throw InputError("point " + std::to_string(k) + " lies " + what +
                   " of the local frame, where its angles are undefined: choose another centre");
}

}  // namespace

// Bae 2002, eq. (2.2).
PolarCoordinates polar_coordinates(const Eigen::Matrix2Xd& p, int threads) {
  PolarCoordinates c{Eigen::VectorXd(p.cols()), Eigen::VectorXd(p.cols())};
  const std::size_t n = static_cast<std::size_t>(p.cols());
  parallel_chunks(n, worker_count(threads, n), [&](std::size_t b, std::size_t e, int) {
    for (Eigen::Index k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k) {
      c.r[k] = std::sqrt(p(0, k) * p(0, k) + p(1, k) * p(1, k));
      if (!(c.r[k] > 0.0)) degenerate(k, "at the centre");
      c.theta[k] = azimuth(p(0, k), p(1, k));
    }
  });
  return c;
}

// Bae 2002, eq. (3.1); φ through atan2 for accuracy near the poles.
SphericalCoordinates spherical_coordinates(const Eigen::Matrix3Xd& p, int threads) {
  const Eigen::Index n = p.cols();
  SphericalCoordinates c{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  parallel_chunks(static_cast<std::size_t>(n), worker_count(threads, static_cast<std::size_t>(n)),
                  [&](std::size_t b, std::size_t e, int) {
    for (Eigen::Index k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k) {
      const double r2 = p(0, k) * p(0, k) + p(1, k) * p(1, k), rxy = std::sqrt(r2);
      c.rho[k] = std::sqrt(r2 + p(2, k) * p(2, k));
      if (!(c.rho[k] > 0.0)) degenerate(k, "at the origin");
      c.phi[k] = std::atan2(rxy, p(2, k));
      c.theta[k] = azimuth(p(0, k), p(1, k));
    }
  });
  return c;
}

// Bae 2002, eq. (3.6).
CylindricalCoordinates cylindrical_coordinates(const Eigen::Matrix3Xd& p, int threads) {
  const Eigen::Index n = p.cols();
  CylindricalCoordinates c{Eigen::VectorXd(n), Eigen::VectorXd(n), p.row(2).transpose()};
  parallel_chunks(static_cast<std::size_t>(n), worker_count(threads, static_cast<std::size_t>(n)),
                  [&](std::size_t b, std::size_t e, int) {
    for (Eigen::Index k = static_cast<Eigen::Index>(b); k < static_cast<Eigen::Index>(e); ++k) {
      c.r[k] = std::sqrt(p(0, k) * p(0, k) + p(1, k) * p(1, k));
      if (!(c.r[k] > 0.0)) degenerate(k, "on the z axis");
      c.theta[k] = azimuth(p(0, k), p(1, k));
    }
  });
  return c;
}

AzimuthRange azimuth_range(const Eigen::VectorXd& theta, double closed_gap) {
  const Eigen::Index n = theta.size();
  if (n == 0) throw InputError("azimuth range: no angles");
  if (closed_gap <= 0.0) closed_gap = std::max(kTwoPi / 36.0, 10.0 * kTwoPi / static_cast<double>(n));
  // Gaps wider than a bin run between consecutive non-empty bins: exact from per-bin extremes.
  const int bins = static_cast<int>(std::clamp<Eigen::Index>(n, 64, 1 << 16));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(bins, inf), hi(bins, -inf);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = theta[k];
    const int b = std::clamp(static_cast<int>(t / kTwoPi * bins), 0, bins - 1);
    lo[b] = std::min(lo[b], t);
    hi[b] = std::max(hi[b], t);
  }
  std::vector<int> full;
  for (int b = 0; b < bins; ++b)
    if (lo[b] <= hi[b]) full.push_back(b);
  AzimuthRange r;
  double gap_start = 0.0, gap_end = 0.0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const int a = full[i], b = full[(i + 1) % full.size()];
    const double g = lo[b] - hi[a] + (i + 1 == full.size() ? kTwoPi : 0.0);  // wraps at the last
    if (g > r.largest_gap) r.largest_gap = g, gap_start = hi[a], gap_end = lo[b];
  }
  if (r.largest_gap <= closed_gap) {
    r.closed = true;
    r.start = 0.0;
    r.end = kTwoPi;
    return r;
  }
  r.start = gap_end;
  r.end = gap_start >= gap_end ? gap_start : gap_start + kTwoPi;
  return r;
}

AzimuthRange azimuth_range(const Eigen::VectorXd& theta, Closure closure, double closed_gap) {
  AzimuthRange r = azimuth_range(theta, closed_gap);
  if (closure == Closure::closed && !r.closed) {
    r.closed = true;
    r.start = 0.0;
    r.end = kTwoPi;
  } else if (closure == Closure::open && r.closed) {
    r = azimuth_range(theta, std::nextafter(r.largest_gap, 0.0));
  }
  return r;
}

void unwrap_angles(Eigen::VectorXd& theta, double start) {
  for (Eigen::Index k = 0; k < theta.size(); ++k) {
    double t = theta[k] - kTwoPi * std::floor((theta[k] - start) / kTwoPi);
    if (t >= start + kTwoPi) t -= kTwoPi;  // rounding at the top end
    theta[k] = t;
  }
}

}  // namespace polarform
