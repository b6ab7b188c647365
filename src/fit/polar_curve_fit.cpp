#include "src/fit/polar_curve_fit.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>

#include "src/error.h"
#include "src/fit/circle_fit.h"
#include "src/fit/fit_pipeline.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/profile_loops.h"
#include "src/fit/trimmed_fit.h"
#include "src/number_text.h"
#include "src/nurbs/symbolic_product.h"
#include "src/units.h"

namespace polarform {

NurbsCurve2d polar_product_curve(const BSplineFunction& F, const BaseCircle& base,
                                 const Eigen::Vector2d& centre) {
  const NurbsCurve2d c = product(F, base.curve());
  Eigen::MatrixXd h = c.homogeneous().coefs();
  h.topRows(2) += centre * h.row(2);
  return NurbsCurve2d(BSpline(c.degree(), c.knots(), std::move(h)));
}

// Bae 2002, §2.2 Steps 1-5.
PolarCurveFit fit_polar_curve(const Eigen::Matrix2Xd& points, const PolarFitOptions& opt) {
  StageClock total, clock;
  if (points.cols() < 4) throw InputError("polar curve fit: " + std::to_string(points.cols()) +
                                          " points, expected at least 4");
  if (!points.allFinite()) throw InputError("polar curve fit: a point is not finite");
  const int threads = opt.function.threads;
  StageTimes times;
  Eigen::Vector2d centre;
  std::ostringstream centre_reason;
  if (opt.centre) {
    centre = *opt.centre;
    centre_reason << "given";
  } else {
    const CircleFit cf = fit_circle(points);
    centre = cf.centre;
    centre_reason << "algebraic circle fit (Taubin): radius " << cf.radius << ", RMS " << cf.rms;
  }
  times.frame = clock.lap();

  // Step 1: polar coordinates (2.2) and the angle range.
  const Eigen::Matrix2Xd local = points.colwise() - centre;
  PolarCoordinates pc = polar_coordinates(local, threads);
  const AzimuthRange range = azimuth_range(pc.theta, opt.closure, opt.closed_gap);
  unwrap_angles(pc.theta, range.start);
  times.sync = clock.lap();

  SingleValuedness check;
  const auto folds = [&] {
    std::ostringstream msg;
    msg.precision(6);
    msg << "polar curve fit: the data is not single-valued about the centre (" << centre.x() << ", "
        << centre.y() << "): rays from it cross the data more than once at "
        << describe_folds(check, "theta (deg)", kDegreesPerRadian) << "; noise " << check.noise
        << ". Choose another centre or split the data into single-valued pieces";
    return InputError(msg.str());
  };
  if (opt.check_single_valued) {
    check = check_single_valued(pc.theta, Eigen::VectorXd(), pc.r, threads);
    if (!check.single_valued) {
      const std::string loops = describe_loops(profile_contours(local), centre);
      if (!loops.empty()) throw InputError("polar curve fit: " + loops);
    }
    require_thin_data(check, "polar curve fit");
  }
  OutlierReport outliers = settle_outliers(
      opt.outliers, pc.theta, Eigen::VectorXd(), pc.r, check, opt.check_single_valued,
      "polar curve fit",
      [&](Eigen::Index k) { return "theta " + number_text(degrees_in_turn(pc.theta[k])) + " deg"; },
      folds, threads);
  times.check = clock.lap();

  // Steps 2-3: base circle (2.3) and synchronization (2.7)-(2.8).
  BaseCircle base = BaseCircle::with_max_sweep(opt.base_kind, range.start, range.end, opt.max_sweep,
                                               opt.alpha_rule, ArcParametrization::angle);
  Samples samples;
  samples.u = Eigen::VectorXd::Zero(points.cols());
  samples.v = synchronize(base, pc.theta, threads);
  samples.value = pc.r;
  times.sync += clock.lap();

  // Step 4: r = F(u) (2.9), measured by true distances to C(u) = F(u)·B(u).
  Eigen::Matrix3Xd local3 = Eigen::Matrix3Xd::Zero(3, points.cols());
  local3.topRows(2) = local;
  FunctionFitOptions fo = with_progress_range(opt.function, 0.1, 0.95);
  fo.degree_u = 0;
  fo.size_u = 1;
  fo.max_size_u = 1;
  const FunctionSpace space{
      0.0, 1.0, base.curve().front(), base.curve().back(), range.closed, false, 0,
      0,   1,   base.arcs()};
  TrimmedFit trimmed = fit_trimmed(
      std::move(samples), local3, space, fo,
      [&base](const BSplineSurface& F) { return ProductGeometry::polar(F, base); }, outliers.points,
      opt.model);
  FunctionFitResult& fit = trimmed.fit;

  // Step 5: C(u) = F(u)·B(u) (2.10), then back to the input coordinates.
  clock.lap();
  const BSplineSurface& Fs = fit.F;
  BSplineFunction F(Fs.degree_v(), Fs.knots_v(), Fs.coefs().row(0).transpose());
  NurbsCurve2d curve = polar_product_curve(F, base, centre);
  times.product = clock.lap();

  FitReport rep = make_report(fit, 0, curve.degree(), 1, curve.size(), trimmed.kept, threads,
                              trimmed.unconverged, times);
  rep.outliers = std::move(outliers);
  rep.net = std::move(trimmed.net);
  rep.restarted = trimmed.restarted;
  rep.revolution = std::move(trimmed.revolution);
  rep.times.total = total.lap();
  return PolarCurveFit{std::move(curve), std::move(F), std::move(base), centre, centre_reason.str(),
                       range.closed, std::move(check), std::move(rep)};
}

PlanarSlice slice_points(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& normal, const Eigen::Vector3d& x_direction,
                         double thickness) {
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw InputError("planar slice: thickness " + std::to_string(thickness) + ", expected > 0");
  if (!(normal.norm() > 0.0)) throw InputError("planar slice: normal must be non-zero");
  const Eigen::Vector3d k = normal.normalized();
  const Eigen::Vector3d ix = x_direction - k * k.dot(x_direction);
  if (!(ix.norm() > 1e-12 * x_direction.norm()))
    throw InputError("planar slice: x_direction must not be parallel to the normal");
  PlanarSlice s;
  s.plane.origin = origin;
  s.plane.axes.col(0) = ix.normalized();
  s.plane.axes.col(1) = k.cross(s.plane.axes.col(0));
  s.plane.axes.col(2) = k;
  std::vector<Eigen::Index> keep;
  for (Eigen::Index c = 0; c < points.cols(); ++c)
    if (std::abs((points.col(c) - origin).dot(k)) <= thickness / 2) keep.push_back(c);
  s.points.resize(2, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t a = 0; a < keep.size(); ++a)
    s.points.col(static_cast<Eigen::Index>(a)) = s.plane.to_local(Eigen::Vector3d(points.col(keep[a]))).head<2>();
  return s;
}

NurbsCurve3d curve_in_space(const NurbsCurve2d& curve, const LocalFrame& plane) {
  const Eigen::MatrixXd& h2 = curve.homogeneous().coefs();
  Eigen::MatrixXd h3 = Eigen::MatrixXd::Zero(4, h2.cols());
  h3.topRows(2) = h2.topRows(2);
  h3.row(3) = h2.row(2);
  return plane.to_global(NurbsCurve3d(BSpline(curve.degree(), curve.knots(), std::move(h3))));
}

}  // namespace polarform
