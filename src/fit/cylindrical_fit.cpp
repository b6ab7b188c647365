#include "src/fit/cylindrical_fit.h"

#include <numbers>
#include <sstream>

#include "src/error.h"
#include "src/fit/fit_pipeline.h"
#include "src/fit/trimmed_fit.h"
#include "src/number_text.h"
#include "src/nurbs/symbolic_product.h"
#include "src/units.h"

namespace polarform {

// Bae 2002, §3.2 with §3.3.1 and §4.3.
CylindricalFit fit_cylindrical(const Eigen::Matrix3Xd& points, const CylindricalFitOptions& opt) {
  StageClock total, clock;
  const int threads = opt.function.threads;
  ProgressRange progress(opt.function.progress, 0.0, 1.0);
  StageTimes times;
  LocalCloud cloud = local_cloud(points, opt.frame, threads, "cylindrical fit");
  FrameEstimate& frame = cloud.frame;
  const Eigen::Matrix3Xd& local = cloud.points;
  times.frame = clock.lap();
  progress(0.05);

  // Cylindrical coordinates (3.6), azimuth and height ranges.
  CylindricalCoordinates cc = cylindrical_coordinates(local, threads);
  const AzimuthRange range = azimuth_range(cc.theta, opt.closure, opt.closed_gap);
  unwrap_angles(cc.theta, range.start);
  const double z0 = cc.z.minCoeff(), z1 = cc.z.maxCoeff();
  if (!(z1 > z0)) throw InputError("cylindrical fit: the data spans no height along the axis");
  times.sync = clock.lap();

  SingleValuedness check;
  // θ becomes the arc r̄·θ, comparable with z, for the checks (in place: 80 MB at 10^7 points).
  const double rbar = cc.r.mean() > 0.0 ? cc.r.mean() : 1.0;
  cc.theta *= rbar;
  const Eigen::VectorXd& arc = cc.theta;
  const auto folds = [&] {
    std::ostringstream msg;
    msg.precision(6);
    msg << "cylindrical fit: the data is not single-valued about the axis through ("
        << frame.frame.origin.transpose() << ") along (" << frame.frame.axes.col(2).transpose()
        << "): rays from it cross the data more than once at "
        << describe_folds(check, "z", 1.0, "theta (deg)", kDegreesPerRadian / rbar) << "; noise "
        << check.noise
        << ". Choose another axis or try the spherical fit; a turned part (a wall with two "
        << "skins, steps) is recovered by `polarform sweep`";
    return InputError(msg.str());
  };
  if (opt.check_single_valued) {
    check = check_single_valued(cc.z, arc, cc.r, threads);
    require_thin_data(check, "cylindrical fit");
  }
  OutlierReport outliers = settle_outliers(
      opt.outliers, cc.z, arc, cc.r, check, opt.check_single_valued, "cylindrical fit",
      [&](Eigen::Index k) {
        return "z " + number_text(cc.z[k]) + " mm, theta " +
               number_text(degrees_in_turn(arc[k] / rbar)) + " deg";
      },
      folds, threads);
  cc.theta /= rbar;
  times.check = clock.lap();
  progress(0.15);

  // Base cylinder (3.7) and synchronization (§3.2).
  BaseCylinder base(opt.base_kind, range.start, range.end, z0, z1, opt.alpha_rule,
                    ArcParametrization::angle, opt.max_sweep);
  Samples samples;
  samples.u = (cc.z.array() - z0) / (z1 - z0);
  samples.v = synchronize(base.azimuth(), cc.theta, threads);
  samples.value = std::move(cc.r);
  // The coordinates are in the samples now: 320 MB fewer at 10^7 points during the fit.
  cc = CylindricalCoordinates{};
  times.sync += clock.lap();

  const FunctionSpace space{0.0,
                            1.0,
                            base.azimuth().curve().front(),
                            base.azimuth().curve().back(),
                            range.closed,
                            false,
                            0,
                            0,
                            1,
                            base.azimuth().arcs()};
  TrimmedFit trimmed = fit_trimmed(
      std::move(samples), local, space, with_progress_range(opt.function, 0.15, 0.95),
      [&base](const BSplineSurface& F) { return ProductGeometry::cylindrical(F, base); },
      outliers.points, opt.model);
  FunctionFitResult& fit = trimmed.fit;

  // S = (F·X, F·Y, Z) (B.3), (3.8), then global coordinates (4.6).
  clock.lap();
  const NurbsSurface local_surface = cylindrical_product(fit.F, base.surface());
  SeamReport seam;
  if (range.closed) seam = seam_continuity(local_surface);
  NurbsSurface surface = frame.frame.to_global(local_surface);
  times.product = clock.lap();
  FitReport rep = make_report(fit, surface.degree_u(), surface.degree_v(), surface.size_u(),
                              surface.size_v(), trimmed.kept, threads, trimmed.unconverged, times);
  rep.outliers = std::move(outliers);
  rep.net = std::move(trimmed.net);
  rep.restarted = trimmed.restarted;
  rep.revolution = std::move(trimmed.revolution);
  rep.times.total = total.lap();
  progress(1.0);
  return CylindricalFit{std::move(surface), std::move(fit.F), std::move(base), std::move(frame),
                        range.closed, seam, std::move(check), std::move(rep)};
}

CylindricalFit fit_cylindrical(const std::filesystem::path& file, const CylindricalFitOptions& options,
                               const ReadOptions& read) {
  StageClock clock;
  const PointCloud cloud = read_point_cloud(file, read);
  const double t = clock.lap();
  CylindricalFit fit = fit_cylindrical(cloud.points, options);
  fit.report.times.read = t;
  fit.report.times.total += t;
  return fit;
}

}  // namespace polarform
