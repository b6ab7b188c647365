#include "src/fit/scalar_field_surface.h"

#include <cmath>
#include <numbers>
#include <string>

#include "src/base/base_cylinder.h"
#include "src/base/base_sphere.h"
#include "src/error.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace {

void check(const Eigen::VectorXd& p, const Eigen::VectorXd& a, const Eigen::VectorXd& b,
           const ScalarFieldOptions& o) {
  if (p.size() < 4 || a.size() != p.size() || b.size() != p.size())
    throw InputError("scalar field: " + std::to_string(p.size()) + " values with " +
                     std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                     " coordinates; expected at least 4 of each, one per value");
  if (!p.allFinite() || !a.allFinite() || !b.allFinite())
    throw InputError("scalar field: a value or coordinate is not finite");
  if (!std::isfinite(o.scale) || !std::isfinite(o.offset) || o.scale == 0.0)
    throw InputError("scalar field: scale must be finite and non-zero, offset finite");
}

// Greville abscissae of a knot vector.
std::vector<double> greville(int p, const Knots& U) {
  const int n = static_cast<int>(U.size()) - p - 1;
  std::vector<double> g(n, 0.0);
  for (int i = 0; i < n; ++i) {
    if (p == 0) g[i] = 0.5 * (U[i] + U[i + 1]);
    for (int k = 1; k <= p; ++k) g[i] += U[i + k] / p;
  }
  return g;
}

// s·F + d as a B-spline (partition of unity: the coefficients map alike); Bae 2002, eq. (5.6).
BSplineSurface scaled(const BSplineSurface& F, double s, double d) {
  return BSplineSurface(F.degree_u(), F.degree_v(), F.knots_u(), F.knots_v(),
                        (s * F.coefs().array() + d).matrix());
}

ScalarFieldSurface finish(NurbsSurface S, BSplineSurface F, const Samples& samples, int threads) {
  ScalarFieldSurface out{std::move(S), std::move(F), {}, 0.0, 0.0, {}};
  const std::vector<double> gu = greville(out.surface.degree_u(), out.surface.knots_u());
  const std::vector<double> gv = greville(out.surface.degree_v(), out.surface.knots_v());
  out.control_values.resize(static_cast<Eigen::Index>(gu.size() * gv.size()));
  for (std::size_t i = 0; i < gu.size(); ++i)
    for (std::size_t j = 0; j < gv.size(); ++j)
      out.F.point(gu[i], gv[j], &out.control_values[static_cast<Eigen::Index>(i * gv.size() + j)]);
  out.min_value = out.control_values.minCoeff();
  out.max_value = out.control_values.maxCoeff();
  out.fit_error = error_stats(parametric_residuals(out.F, samples, threads));
  return out;
}

}  // namespace

// Bae 2002, §5.3 on a base sphere.
ScalarFieldSurface visualize_spherical(const Eigen::VectorXd& p, const Eigen::VectorXd& phi,
                                       const Eigen::VectorXd& theta_in, const ScalarFieldOptions& o) {
  check(p, phi, theta_in, o);
  if (phi.minCoeff() < 0.0 || phi.maxCoeff() > std::numbers::pi)
    throw InputError("scalar field: polar angles must lie in [0, pi]");
  Eigen::VectorXd theta = theta_in.array() - 2 * std::numbers::pi * (theta_in.array() / (2 * std::numbers::pi)).floor();
  const AzimuthRange range = azimuth_range(theta, o.closure);
  unwrap_angles(theta, range.start);
  const double phi0 = phi.minCoeff(), phi1 = phi.maxCoeff();
  if (!(phi1 > phi0)) throw InputError("scalar field: the polar angles span no range");
  const BaseSphere base(o.base_kind, phi0, phi1, range.start, range.end, AlphaRule::minimax,
                        ArcParametrization::angle, o.max_sweep);
  Samples s;
  s.u.resize(p.size()), s.v.resize(p.size());
  base.meridian().parameters(phi.data(), s.u.data(), static_cast<std::size_t>(p.size()));
  base.azimuth().parameters(theta.data(), s.v.data(), static_cast<std::size_t>(p.size()));
  s.value = p;
  const FunctionSpace space{phi0, phi1, range.start, range.end, range.closed};
  FunctionFitResult fit = fit_function(s, space, o.function);
  NurbsSurface S = product(scaled(fit.F, o.scale, o.offset), base.surface());
  return finish(std::move(S), std::move(fit.F), s, o.function.threads);
}

// Bae 2002, §5.3 on a base cylinder (z untouched, as in (B.3)).
ScalarFieldSurface visualize_cylindrical(const Eigen::VectorXd& p, const Eigen::VectorXd& theta_in,
                                         const Eigen::VectorXd& z, const ScalarFieldOptions& o) {
  check(p, theta_in, z, o);
  Eigen::VectorXd theta = theta_in.array() - 2 * std::numbers::pi * (theta_in.array() / (2 * std::numbers::pi)).floor();
  const AzimuthRange range = azimuth_range(theta, o.closure);
  unwrap_angles(theta, range.start);
  const double z0 = z.minCoeff(), z1 = z.maxCoeff();
  if (!(z1 > z0)) throw InputError("scalar field: the heights span no range");
  const BaseCylinder base(o.base_kind, range.start, range.end, z0, z1, AlphaRule::minimax,
                          ArcParametrization::angle, o.max_sweep);
  Samples s;
  s.u = (z.array() - z0) / (z1 - z0);
  s.v.resize(p.size());
  base.azimuth().parameters(theta.data(), s.v.data(), static_cast<std::size_t>(p.size()));
  s.value = p;
  const FunctionSpace space{0.0, 1.0, range.start, range.end, range.closed};
  FunctionFitResult fit = fit_function(s, space, o.function);
  NurbsSurface S = cylindrical_product(scaled(fit.F, o.scale, o.offset), base.surface());
  return finish(std::move(S), std::move(fit.F), s, o.function.threads);
}

}  // namespace polarform
