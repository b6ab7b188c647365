#include "jobs/fit/fit_job.h"

#include <cmath>
#include <sstream>

#include "src/error.h"
#include "src/io/point_cloud.h"

namespace polarform {

namespace {

FunctionFitOptions function_options(const FitJobOptions& o) {
  if (o.ctrl && o.tolerance)
    throw InputError("give either a control net (--ctrl) or a tolerance (--tol), not both");
  if (o.tolerance && !(*o.tolerance > 0.0))
    throw InputError("tolerance must be a positive number of mm");
  if (o.threads < 1) throw InputError("threads must be at least 1");
  if (!(o.fairness_weight > 0.0) || !std::isfinite(o.fairness_weight))
    throw InputError("the fairness weight λ must be a positive number");
  FunctionFitOptions f;
  f.fairness.mode = o.fairness;
  f.fairness.weight = o.fairness_weight;
  if (o.degree) f.degree_u = o.degree->first, f.degree_v = o.degree->second;
  if (o.ctrl) f.size_u = o.ctrl->first, f.size_v = o.ctrl->second;
  if (o.tolerance) f.tolerance = *o.tolerance, f.measure = o.measure;
  f.threads = o.threads;
  f.progress = o.fit_progress;
  return f;
}

std::string plane_text(const CloudPlane& p) {
  std::ostringstream s;
  s.precision(4);
  s << "rms distance " << p.rms_distance << " mm from their best-fit plane, "
    << p.rms_distance / p.size << " of their size " << p.size << " mm (planar below 0.001)";
  return s.str();
}

void fit_polar(FitJobResult& r, const FitJobOptions& o) {
  PolarFitOptions po;
  po.function = function_options(o);
  po.closure = o.closure;
  po.base_kind = o.base;
  if (o.center) po.centre = r.plane.frame.to_local(*o.center).head<2>();
  const Eigen::Matrix2Xd local = r.plane.frame.to_local(r.points).topRows(2);
  r.polar = fit_polar_curve(local, po);
  r.curve = curve_in_space(r.polar->curve, r.plane.frame);
  r.method = "polar";
}

void fit_surface(FitJobResult& r, const FitJobOptions& o) {
  RotationalFitOptions ro;
  ro.spherical.function = ro.cylindrical.function = function_options(o);
  ro.spherical.frame.origin = ro.cylindrical.frame.origin = o.center;
  ro.spherical.frame.axis = ro.cylindrical.frame.axis = o.axis;
  ro.spherical.closure = ro.cylindrical.closure = o.closure;
  ro.spherical.base_kind = ro.cylindrical.base_kind = o.base;
  if (o.pole) ro.spherical.north = ro.spherical.south = *o.pole;
  if (o.method == FitJobMethod::spherical) ro.method = FitMethod::spherical;
  if (o.method == FitJobMethod::cylindrical) ro.method = FitMethod::cylindrical;
  r.surface = fit_rotational(r.points, ro);
  r.method = to_string(r.surface->method);
}

FitJobResult run(Eigen::Matrix3Xd points, const std::string& name, const FitJobOptions& o,
                 double read_seconds) {
  StageClock clock;
  FitJobResult r;
  r.input = name;
  r.points = std::move(points);
  r.fairness = o.fairness;
  r.fairness_weight = o.fairness_weight;
  r.base = o.base;
  if (o.pole && *o.pole == PoleTreatment::cap && o.closure == Closure::open)
    throw InputError(
        "a pole cap closes a closed spherical fit: --pole cap needs --closed auto or yes");
  r.plane = fit_plane(r.points, o.method == FitJobMethod::polar ? o.axis : std::nullopt);
  const bool planar = r.plane.planar();
  switch (o.method) {
    case FitJobMethod::polar:
      if (!planar)
        throw InputError(name + ": --method polar needs a planar profile, but the points have " +
                         plane_text(r.plane));
      fit_polar(r, o);
      r.reason = "polar fit requested (the points have " + plane_text(r.plane) + ")";
      break;
    case FitJobMethod::automatic:
      if (planar) {
        if (o.axis) r.plane = fit_plane(r.points, o.axis);
        fit_polar(r, o);
        r.reason = "the points have " + plane_text(r.plane) +
                   ": a profile, polar curve fit (centre: " + r.polar->centre_reason + ")";
        break;
      }
      fit_surface(r, o);
      r.reason = r.surface->reason;
      break;
    case FitJobMethod::spherical:
    case FitJobMethod::cylindrical:
      fit_surface(r, o);
      r.reason = r.surface->reason;
      break;
  }
  if (r.surface) {
    FitReport& rep =
        r.surface->spherical ? r.surface->spherical->report : r.surface->cylindrical->report;
    rep.times.read = read_seconds;
    rep.times.total += read_seconds;
  } else {
    r.polar->report.times.read = read_seconds;
    r.polar->report.times.total += read_seconds;
  }
  r.seconds = read_seconds + clock.lap();
  return r;
}

}  // namespace

FitJobOptions fit_job_options(const FitProject& p) {
  FitJobOptions o;
  o.method = p.method;
  o.closure = p.closure;
  o.pole = p.pole;
  o.degree = p.degree;
  o.ctrl = p.ctrl;
  o.tolerance = p.tolerance;
  o.measure = p.measure;
  o.center = p.center;
  o.axis = p.axis;
  o.skip_bad = p.skip_bad;
  o.fairness = p.fairness;
  o.fairness_weight = p.fairness_weight;
  o.base = p.base;
  return o;
}

FitJobResult run_fit_job(const std::filesystem::path& scan, const FitJobOptions& o) {
  StageClock clock;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  ro.progress = o.read_progress;
  PointCloud cloud = read_point_cloud(scan, ro);
  const double read_seconds = clock.lap();
  FitJobResult r = run(std::move(cloud.points), scan.string(), o, read_seconds);
  r.dropped = cloud.dropped;
  return r;
}

FitJobResult run_fit_job(Eigen::Matrix3Xd points, const std::string& name, const FitJobOptions& o) {
  return run(std::move(points), name, o, 0.0);
}

}  // namespace polarform
