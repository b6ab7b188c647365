#include "jobs/fit/fit_job.h"

#include <cmath>
#include <sstream>

#include "jobs/fit/surface_fairing_stage.h"
#include "src/error.h"
#include "src/io/point_cloud.h"
#include "src/number_text.h"

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

OutlierPolicy outlier_policy(const FitJobOptions& o) {
  return o.reject_outliers ? OutlierPolicy::reject : OutlierPolicy::refuse;
}

RotationalFitOptions rotational_options(const FitJobOptions& o) {
  if (o.ctrl) check_control_net_size(o.ctrl->first, o.ctrl->second, "--ctrl");
  RotationalFitOptions ro;
  ro.spherical.outliers = ro.cylindrical.outliers = outlier_policy(o);
  ro.spherical.function = ro.cylindrical.function = function_options(o);
  ro.spherical.frame.origin = ro.cylindrical.frame.origin = o.center;
  ro.spherical.frame.axis = ro.cylindrical.frame.axis = o.axis;
  ro.spherical.closure = ro.cylindrical.closure = o.closure;
  ro.spherical.base_kind = ro.cylindrical.base_kind = o.base;
  ro.spherical.model.revolution = ro.cylindrical.model.revolution = o.revolution;
  if (o.pole) ro.spherical.north = ro.spherical.south = *o.pole;
  if (o.method == FitJobMethod::spherical) ro.method = FitMethod::spherical;
  if (o.method == FitJobMethod::cylindrical) ro.method = FitMethod::cylindrical;
  return ro;
}

void check_options(const FitJobOptions& o) {
  function_options(o);
  if (o.pole && *o.pole == PoleTreatment::cap && o.closure == Closure::open)
    throw InputError(
        "a pole cap closes a closed spherical fit: --pole cap needs --closed auto or yes");
}

// The plane the method choice looks at: with --method polar an axis is the plane's normal.
CloudPlane choice_plane(const FitInput& in, const FitJobOptions& o) {
  return naming_input(in.file.string(), [&] {
    return fit_plane(in.points, o.method == FitJobMethod::polar ? o.axis : std::nullopt);
  });
}

// Whether the polar method runs: asked for (the points must then be planar), or automatic on a
// planar cloud.
bool runs_polar(const FitInput& in, const CloudPlane& plane, const FitJobOptions& o) {
  if (o.method == FitJobMethod::polar && !plane.planar())
    throw InputError(in.file.string() +
                     ": --method polar needs a planar profile, but the points have " +
                     plane_text(plane));
  return o.method == FitJobMethod::polar || (o.method == FitJobMethod::automatic && plane.planar());
}

ProfileFit fit_profile(const FitInput& in, const CloudPlane& plane, const FitJobOptions& o) {
  PolarFitOptions po;
  po.function = function_options(o);
  po.closure = o.closure;
  po.base_kind = o.base;
  po.model.revolution = o.revolution;
  po.outliers = outlier_policy(o);
  if (o.center) po.centre = plane.frame.to_local(*o.center).head<2>();
  const Eigen::Matrix2Xd local = plane.frame.to_local(in.points).topRows(2);
  PolarCurveFit polar = fit_polar_curve(local, po);
  std::optional<ProfileFairing> fairing;
  std::optional<ProfileInterrogation> before;
  if (o.fairing) {
    before = interrogate_profile(polar);
    fairing = fair_polar_curve(polar, local, *o.fairing);
  }
  NurbsCurve3d curve = curve_in_space(polar.curve, plane.frame);
  ProfileInterrogation interrogation = interrogate_profile(polar);
  return {std::move(polar), std::move(curve), std::move(interrogation), std::move(fairing),
          std::move(before)};
}

// A closed pole that creases or rests on no data (SphericalFit::north_check, south_check).
void add_pole_warnings(const SphericalFit& f, double reach, std::vector<std::string>& warnings) {
  const std::pair<const char*, const PoleCheck*> poles[] = {{"north", &f.north_check},
                                                            {"south", &f.south_check}};
  for (const auto& [name, check] : poles) {
    const std::optional<PoleReport>& measured = name[0] == 'n' ? f.north_pole : f.south_pole;
    if (check->creased)
      warnings.push_back("spherical fit: the " + std::string(name) +
                         " pole creases: its normals spread by " +
                         degrees_text(measured->normal_spread) + " about their mean (more than " +
                         degrees_text(kMaxPoleNormalSpread) +
                         "), so it has no tangent plane; --pole g1 gives it one");
    if (check->extrapolated)
      warnings.push_back("spherical fit: the " + std::string(name) +
                         " pole is extrapolated: no data within " + degrees_text(reach) +
                         " of it (the nearest point is " + degrees_text(check->nearest_data) +
                         " away)");
  }
}

FitReport& report_of(std::variant<ProfileFit, RotationalFit>& fit) {
  if (auto* p = std::get_if<ProfileFit>(&fit)) return p->polar.report;
  return std::get<RotationalFit>(fit).report();
}

}  // namespace

const FitReport& FitJobResult::report() const {
  if (const auto* p = std::get_if<ProfileFit>(&fit)) return p->polar.report;
  return std::get<RotationalFit>(fit).report();
}

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
  o.reject_outliers = p.reject_outliers;
  o.fairness = p.fairness;
  o.fairness_weight = p.fairness_weight;
  o.base = p.base;
  o.revolution = p.revolution;
  return o;
}

FitInput read_fit_input(const std::filesystem::path& scan, const FitJobOptions& o) {
  StageClock clock;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  ro.progress = o.read_progress;
  PointCloud cloud = read_point_cloud(scan, ro);
  return {scan, std::move(cloud.points), cloud.dropped, clock.lap()};
}

FitPreview preview_fit(const FitInput& in, const FitJobOptions& o) {
  check_options(o);
  FitPreview p;
  p.plane = choice_plane(in, o);
  p.profile = runs_polar(in, p.plane, o);
  if (p.profile) return p;
  try {
    p.frame = estimate_frame(in.points, rotational_options(o).spherical.frame);
  } catch (const InputError& e) {
    p.frame_error = std::string("local frame: ") + e.what();
  }
  return p;
}

FitJobResult fit_cloud(FitInput in, const FitJobOptions& o) {
  StageClock clock;
  check_options(o);
  CloudPlane plane = choice_plane(in, o);
  const bool polar = runs_polar(in, plane, o);
  // Automatic on a planar cloud: a given axis is the profile plane's normal.
  if (polar && o.method == FitJobMethod::automatic && o.axis)
    plane = naming_input(in.file.string(), [&] { return fit_plane(in.points, o.axis); });
  if (o.interrogate && polar)
    throw InputError(
        "--interrogate: a profile has no surface to interrogate (its curvature is in "
        "curvature.svg); this cloud is " +
        plane_text(plane));
  const RotationalFitOptions rotational = polar ? RotationalFitOptions{} : rotational_options(o);
  std::variant<ProfileFit, RotationalFit> fit = naming_input(in.file.string(), [&] {
    return polar ? std::variant<ProfileFit, RotationalFit>(fit_profile(in, plane, o))
                 : std::variant<ProfileFit, RotationalFit>(fit_rotational(in.points, rotational));
  });
  std::optional<SurfaceFitFairing> surface_fairing;
  if (auto* r = std::get_if<RotationalFit>(&fit); r && o.fairing)
    surface_fairing = fair_surface_fit(*r, in.points, *o.fairing);
  std::string method, reason;
  if (const auto* p = std::get_if<ProfileFit>(&fit)) {
    method = "polar";
    reason = o.method == FitJobMethod::polar
                 ? "polar fit requested (the points have " + plane_text(plane) + ")"
                 : "the points have " + plane_text(plane) +
                       ": a profile, polar curve fit (centre: " + p->polar.centre_reason + ")";
  } else {
    const RotationalFit& s = std::get<RotationalFit>(fit);
    method = to_string(s.method());
    reason = s.reason;
  }
  std::vector<std::string> warnings;
  if (const auto* r = std::get_if<RotationalFit>(&fit))
    if (const auto* sphere = std::get_if<SphericalFit>(&r->fit))
      add_pole_warnings(*sphere, rotational.spherical.pole_reach, warnings);
  FitReport& rep = report_of(fit);
  rep.times.read = in.read_seconds;
  rep.times.total += in.read_seconds;
  FitJobResult result{std::move(in.file),
                      std::move(in.points),
                      in.dropped,
                      std::move(method),
                      std::move(reason),
                      std::move(plane),
                      std::move(fit),
                      o.fairness,
                      o.fairness_weight,
                      o.base,
                      o.reject_outliers,
                      std::move(warnings),
                      in.read_seconds + clock.lap(),
                      std::nullopt,
                      std::move(surface_fairing)};
  if (o.interrogate) {
    const RotationalFit& f = std::get<RotationalFit>(result.fit);
    std::vector<NurbsSurface> surfaces{f.surface()};
    if (const auto* sphere = std::get_if<SphericalFit>(&f.fit))
      for (const std::optional<PoleCap>* cap : {&sphere->north_cap, &sphere->south_cap})
        if (*cap) surfaces.push_back((*cap)->surface);
    result.interrogation = interrogate_surfaces(surfaces, *o.interrogate);
  }
  return result;
}

FitJobResult run_fit_job(const std::filesystem::path& scan, const FitJobOptions& o) {
  return fit_cloud(read_fit_input(scan, o), o);
}

FitJobResult run_fit_job(Eigen::Matrix3Xd points, const std::string& name, const FitJobOptions& o) {
  return fit_cloud(FitInput{name, std::move(points), 0, 0.0}, o);
}

}  // namespace polarform
