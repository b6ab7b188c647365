#include "src/fit/spherical_fit.h"

#include <numbers>
#include <sstream>

#include "src/error.h"
#include "src/fit/fit_pipeline.h"
#include "src/fit/trimmed_fit.h"
#include "src/number_text.h"
#include "src/nurbs/symbolic_product.h"
#include "src/units.h"

namespace polarform {

namespace {

PoleCap cap_to_global(PoleCap cap, const LocalFrame& f) {
  cap.surface = f.to_global(cap.surface);
  cap.point = f.to_global(cap.point);
  cap.normal = f.axes * cap.normal;
  cap.pole.point = f.to_global(cap.pole.point);
  cap.pole.normal = f.axes * cap.pole.normal;
  return cap;
}

PoleTreatment resolve(PoleTreatment t, bool near) {
  return t != PoleTreatment::automatic ? t : near ? PoleTreatment::g0 : PoleTreatment::none;
}

// Rows of F tied at the pole (CoefficientMap): 1 for G0 (3.14a), 2 for G1 (3.14).
int pole_rows(PoleTreatment t) { return t == PoleTreatment::g0 ? 1 : t == PoleTreatment::g1 ? 2 : 0; }

PoleReport pole_to_global(PoleReport p, const LocalFrame& f) {
  p.point = f.to_global(p.point);
  p.normal = f.axes * p.normal;
  return p;
}

// The pole's distance from the data (polar angle `nearest`) and its measured normal spread judged.
PoleCheck pole_check(PoleTreatment t, double nearest, const std::optional<PoleReport>& measured,
                     double reach) {
  PoleCheck c;
  c.nearest_data = nearest;
  c.extrapolated = t != PoleTreatment::none && nearest > reach;
  c.creased = measured && measured->normal_spread > kMaxPoleNormalSpread;
  return c;
}

}  // namespace

// Bae 2002, §3.1 Steps 1-5 with §3.3 and §4.3.
SphericalFit fit_spherical(const Eigen::Matrix3Xd& points, const SphericalFitOptions& opt) {
  StageClock total, clock;
  const int threads = opt.function.threads;
  ProgressRange progress(opt.function.progress, 0.0, 1.0);
  StageTimes times;
  LocalCloud cloud = local_cloud(points, opt.frame, threads, "spherical fit");
  FrameEstimate& frame = cloud.frame;
  const Eigen::Matrix3Xd& local = cloud.points;
  times.frame = clock.lap();
  progress(0.05);

  // Step 1: spherical coordinates (3.1) and angle ranges (3.2).
  SphericalCoordinates sc = spherical_coordinates(local, threads);
  const AzimuthRange range = azimuth_range(sc.theta, opt.closure, opt.closed_gap);
  unwrap_angles(sc.theta, range.start);
  const double data_phi0 = sc.phi.minCoeff(), data_phi1 = sc.phi.maxCoeff();
  double phi0 = data_phi0, phi1 = data_phi1;
  const PoleTreatment north = resolve(opt.north, phi0 <= opt.pole_reach);
  const PoleTreatment south = resolve(opt.south, phi1 >= std::numbers::pi - opt.pole_reach);
  if ((north == PoleTreatment::cap || south == PoleTreatment::cap) && !range.closed)
    throw InputError(
        "spherical fit: a pole cap needs a closed fit, but the data leaves an "
        "azimuth gap of " +
        std::to_string(range.largest_gap * kDegreesPerRadian) + " deg");
  if (north == PoleTreatment::g0 || north == PoleTreatment::g1) phi0 = 0.0;
  if (south == PoleTreatment::g0 || south == PoleTreatment::g1) phi1 = std::numbers::pi;
  if (!(phi1 > phi0)) throw InputError("spherical fit: the data spans no polar angle");
  times.sync = clock.lap();

  SingleValuedness check;
  const auto folds = [&] {
    std::ostringstream msg;
    msg.precision(6);
    msg << "spherical fit: the data is not single-valued about the origin ("
        << frame.frame.origin.transpose() << "): rays from it cross the data more than once at "
        << describe_folds(check, "phi (deg)", kDegreesPerRadian, "theta (deg)", kDegreesPerRadian)
        << "; noise " << check.noise
        << ". Choose another centre or try the cylindrical fit; a turned part (a wall with two "
        << "skins, steps) is recovered by `polarform sweep`";
    return InputError(msg.str());
  };
  if (opt.check_single_valued) {
    check = check_single_valued(sc.phi, sc.theta, sc.rho, threads);
    require_thin_data(check, "spherical fit");
  }
  OutlierReport outliers = settle_outliers(
      opt.outliers, sc.phi, sc.theta, sc.rho, check, opt.check_single_valued, "spherical fit",
      [&](Eigen::Index k) {
        return "phi " + number_text(to_degrees(sc.phi[k])) + " deg, theta " +
               number_text(degrees_in_turn(sc.theta[k])) + " deg";
      },
      folds, threads);
  times.check = clock.lap();
  progress(0.15);

  // Steps 2-3: base sphere (3.3) and synchronization.
  BaseSphere base(opt.base_kind, phi0, phi1, range.start, range.end, opt.alpha_rule,
                  ArcParametrization::angle, opt.max_sweep);
  Samples samples;
  samples.u = synchronize(base.meridian(), sc.phi, threads);
  samples.v = synchronize(base.azimuth(), sc.theta, threads);
  samples.value = std::move(sc.rho);
  times.sync += clock.lap();

  // Step 4: ρ = F(u, v) (3.4), closed (3.9)-(3.10) and pole conditions (3.14) as required.
  const bool cap = north == PoleTreatment::cap || south == PoleTreatment::cap;
  const FunctionSpace space{base.meridian().curve().front(),
                            base.meridian().curve().back(),
                            base.azimuth().curve().front(),
                            base.azimuth().curve().back(),
                            range.closed,
                            cap,
                            pole_rows(north),
                            pole_rows(south),
                            base.meridian().arcs(),
                            base.azimuth().arcs()};
  TrimmedFit trimmed = fit_trimmed(
      std::move(samples), local, space, with_progress_range(opt.function, 0.15, 0.95),
      [&base](const BSplineSurface& F) { return ProductGeometry::spherical(F, base); },
      outliers.points, opt.model);
  FunctionFitResult& fit = trimmed.fit;

  // Step 5: S = F·B (3.5), caps, continuity, then global coordinates (4.6).
  clock.lap();
  const NurbsSurface local_surface = product(fit.F, base.surface());
  std::optional<PoleCap> north_cap, south_cap;
  if (north == PoleTreatment::cap) north_cap = cap_to_global(build_pole_cap(local_surface, true), frame.frame);
  if (south == PoleTreatment::cap) south_cap = cap_to_global(build_pole_cap(local_surface, false), frame.frame);
  SeamReport seam;
  if (range.closed) seam = seam_continuity(local_surface);
  std::optional<PoleReport> north_pole, south_pole;
  if (pole_rows(north) > 0) north_pole = pole_to_global(pole_continuity(local_surface, true), frame.frame);
  if (pole_rows(south) > 0) south_pole = pole_to_global(pole_continuity(local_surface, false), frame.frame);
  const PoleCheck north_check = pole_check(north, data_phi0, north_pole, opt.pole_reach);
  const PoleCheck south_check =
      pole_check(south, std::numbers::pi - data_phi1, south_pole, opt.pole_reach);
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
  return SphericalFit{std::move(surface),
                      std::move(north_cap),
                      std::move(south_cap),
                      std::move(fit.F),
                      std::move(base),
                      std::move(frame),
                      range.closed,
                      seam,
                      north,
                      south,
                      north_pole,
                      south_pole,
                      north_check,
                      south_check,
                      std::move(check),
                      std::move(rep)};
}

SphericalFit fit_spherical(const std::filesystem::path& file, const SphericalFitOptions& options,
                           const ReadOptions& read) {
  StageClock clock;
  const PointCloud cloud = read_point_cloud(file, read);
  const double t = clock.lap();
  SphericalFit fit = fit_spherical(cloud.points, options);
  fit.report.times.read = t;
  fit.report.times.total += t;
  return fit;
}

}  // namespace polarform
