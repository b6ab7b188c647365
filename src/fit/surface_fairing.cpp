#include "src/fit/surface_fairing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/fit/continuity.h"
#include "src/fit/error_stats.h"
#include "src/fit/point_distances.h"
#include "src/fit/product_geometry.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace {

// One direction of the net as a curve (`along` is F.along_u() or F.along_v()), faired.
BSpline fair_direction(const BSpline& along, FairingMethod method, const FairingOptions& o,
                       NetDirectionFairing& out) {
  out.max_jump_before = max_top_derivative_jump(along);
  CurveFairing f =
      method == FairingMethod::farin ? farin_fair(along, o, 1) : kjellander_fair_spline(along, o);
  out.steps = std::move(f.steps);
  out.bound = f.total_bound;
  out.max_jump_after = max_top_derivative_jump(f.spline);
  return std::move(f.spline);
}

// F faired along u, then along v, half the tolerance each.
BSplineSurface fair_net(const BSplineSurface& F, const ProfileFairingOptions& options,
                        double tolerance, int fixed_u, int fixed_v, SurfaceFitFairing& r) {
  FairingOptions o;
  o.tolerance = tolerance / 2;
  o.max_passes = options.max_passes;
  o.fixed_end_points = fixed_u;
  const BSplineSurface Fu = BSplineSurface::from_along_u(
      fair_direction(F.along_u(), options.method, o, r.u), F.degree_v(), F.knots_v(), F.dim());
  o.fixed_end_points = fixed_v;
  return BSplineSurface::from_along_v(fair_direction(Fu.along_v(), options.method, o, r.v),
                                      Fu.degree_u(), Fu.knots_u(), Fu.dim());
}

double deviation(const NurbsSurface& a, const NurbsSurface& b) {
  double d = 0.0;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) {
      const double u = a.front_u() + (a.back_u() - a.front_u()) * i / 200;
      const double v = a.front_v() + (a.back_v() - a.front_v()) * j / 200;
      d = std::max(d, (a.point(u, v) - b.point(u, v)).norm());
    }
  return d;
}

// θ wrapped into the base circle's range (a closed circle wraps it itself).
double azimuth_in(const BaseCircle& c, double theta) {
  const double t0 = c.breakpoints().front(), t1 = c.breakpoints().back();
  if (c.closed()) return theta;
  const double w =
      t0 + std::fmod(std::fmod(theta - t0, 2 * std::numbers::pi) + 2 * std::numbers::pi,
                     2 * std::numbers::pi);
  // Beyond the open range: the nearer end (across the gap).
  if (w <= t1) return w;
  return (w - t1) < (t0 + 2 * std::numbers::pi - w) ? t1 : t0;
}

// The fit's report re-measured on `geometry`: true distances from starts on the base's rays.
template <class StartParameters>
void remeasure(FitReport& report, const ProductGeometry& geometry, const Eigen::Matrix3Xd& local,
               StartParameters&& start) {
  Eigen::VectorXd u(local.cols()), v(local.cols());
  for (Eigen::Index k = 0; k < local.cols(); ++k) {
    const Eigen::Vector2d uv = start(Eigen::Vector3d(local.col(k)));
    u[k] = uv.x();
    v[k] = uv.y();
  }
  const PointDistances d = point_distances(geometry, local, u, v, 2);
  std::vector<char> left_out(static_cast<std::size_t>(local.cols()), 0);
  for (const Eigen::Index k : report.outliers.points) left_out[static_cast<std::size_t>(k)] = 1;
  std::vector<double> kept;
  for (Eigen::Index k = 0; k < local.cols(); ++k)
    if (!left_out[static_cast<std::size_t>(k)]) kept.push_back(d.signed_distance[k]);
  report.signed_distance = d.signed_distance;
  report.error = error_stats(
      Eigen::Map<const Eigen::VectorXd>(kept.data(), static_cast<Eigen::Index>(kept.size())));
  report.unconverged = d.unconverged;
  report.restarted = d.restarted;
}

// The fairing of either fit: F faired (u keeps `fixed_u` end rows), S rebuilt by `multiply`
// (F ↦ the local NURBS), its seam and move measured, the error measured again on `geometry`.
template <class Fit, class Multiply, class Geometry, class StartParameters>
SurfaceFitFairing fair_fit(Fit& fit, const Eigen::Matrix3Xd& points,
                           const ProfileFairingOptions& options, int fixed_u, Multiply&& multiply,
                           Geometry&& geometry, StartParameters&& start) {
  SurfaceFitFairing r;
  r.method = options.method;
  r.tolerance = fairing_tolerance(options, fit.report.error.rms);
  r.error_before = fit.report.error.max;
  fit.F = fair_net(fit.F, options, r.tolerance, fixed_u, fit.closed ? fit.F.degree_v() : 0, r);
  const NurbsSurface before = fit.surface;
  const NurbsSurface local = multiply(fit.F);
  if (fit.closed) fit.seam = seam_continuity(local);
  fit.surface = fit.frame.frame.to_global(local);
  r.measured_deviation = deviation(fit.surface, before);
  remeasure(fit.report, geometry(fit.F), fit.frame.frame.to_local(points), start);
  return r;
}

}  // namespace

SurfaceFitFairing fair_cylindrical_fit(CylindricalFit& fit, const Eigen::Matrix3Xd& points,
                                       const ProfileFairingOptions& options) {
  const BaseCylinder& base = fit.base;
  return fair_fit(
      fit, points, options, 0,
      [&](const BSplineSurface& F) { return cylindrical_product(F, base.surface()); },
      [&](const BSplineSurface& F) { return ProductGeometry::cylindrical(F, base); },
      [&](const Eigen::Vector3d& p) {
        const double z = std::clamp(p.z(), base.z_start(), base.z_end());
        return base.parameters(azimuth_in(base.azimuth(), std::atan2(p.y(), p.x())), z);
      });
}

SurfaceFitFairing fair_spherical_fit(SphericalFit& fit, const Eigen::Matrix3Xd& points,
                                     const ProfileFairingOptions& options) {
  if (fit.north_cap || fit.south_cap)
    throw InputError(
        "--fair: this spherical fit closes a pole with a cap, which is built from the surface "
        "it closes; fair a fit without caps (--pole none|g0)");
  if (fit.north == PoleTreatment::g1 || fit.south == PoleTreatment::g1)
    throw InputError(
        "--fair: this spherical fit closes a pole with G1 continuity, which fairing along v "
        "would not keep (a G0 pole's constant row it does); use --pole none|g0");
  const BaseSphere& base = fit.base;
  const std::vector<double>& phis = base.meridian().breakpoints();
  return fair_fit(
      fit, points, options, fit.F.degree_u(),
      [&](const BSplineSurface& F) { return product(F, base.surface()); },
      [&](const BSplineSurface& F) { return ProductGeometry::spherical(F, base); },
      [&](const Eigen::Vector3d& p) {
        const double phi =
            std::clamp(std::atan2(p.head<2>().norm(), p.z()), phis.front(), phis.back());
        return base.parameters(phi, azimuth_in(base.azimuth(), std::atan2(p.y(), p.x())));
      });
}

}  // namespace polarform
