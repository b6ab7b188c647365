#include "jobs/scan_cam/scan_cam_job.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "src/error.h"
#include "src/fit/stage_times.h"
#include "src/io/point_cloud.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// A base radius far from the nominal's (beyond 5 tolerances and 2 % of it) is no wear: the scan
// is likely of another cam than the nominal describes.
std::optional<std::string> wrong_nominal_warning(const ScanCamJobResult& r,
                                                 const ScanCamJobOptions& o) {
  const double nominal = r.nominal->base_radius(), scanned = r.scan.base_radius;
  const double limit = std::max(o.tolerance ? 5.0 * *o.tolerance : 0.0, 0.02 * nominal);
  if (!(std::abs(scanned - nominal) > limit)) return std::nullopt;
  return "the scan's base radius " + number_text(scanned) + " mm differs from the nominal's " +
         number_text(nominal) + " mm by " + number_text(scanned - nominal) + " mm: is " +
         r.nominal_file.string() + " this cam's design (wrong nominal?)";
}

}  // namespace

ScanCamJobResult run_scan_cam_job(const std::filesystem::path& scan, const ScanCamJobOptions& o) {
  StageClock clock;
  ScanCamJobResult r;
  r.input = scan;
  ScannedCamOptions so;
  if (o.nominal) {
    if (o.follower || o.rotation)
      throw InputError("the follower and the sense of rotation come from the nominal design " +
                       o.nominal->string() + "; do not give them as options");
    r.nominal_file = *o.nominal;
    r.nominal_project = read_cam_project(*o.nominal, r.warnings, o.nominal_names);
    if (r.nominal_project->cam.type != CamType::Plate)
      throw InputError(o.nominal->string() + ": a " +
                       std::string(cam_type_name(r.nominal_project->cam.type)) +
                       " cam; scan-cam inspects plate cams");
    r.nominal = make_plate_cam(r.nominal_project->cam);
    so.follower = r.nominal->follower();
    so.rotation = r.nominal->rotation();
    so.nominal = r.nominal;
    r.follower_source = "nominal design";
  } else {
    if (o.tolerance)
      throw InputError("--tol is a tolerance band about the nominal profile: it needs --nominal");
    so.follower = o.follower.value_or(Follower{FollowerKind::KnifeEdge, 0.0, 0.0});
    so.rotation = o.rotation.value_or(Rotation::CounterClockwise);
    if (so.follower.kind == FollowerKind::Roller && !(so.follower.roller_radius > 0))
      throw InputError("a roller follower needs its radius: give --roller-radius MM");
    r.follower_source = o.follower ? "options" : "default (radial knife-edge)";
  }
  if (o.tolerance && !(*o.tolerance > 0)) throw InputError("--tol must be a positive number of mm");
  if (o.threads < 1) throw InputError("threads must be at least 1");
  so.profile.axis = o.axis;
  so.profile.centre = o.center;
  so.threads = o.threads;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  ro.progress = o.read_progress;
  const PointCloud cloud = read_point_cloud(scan, ro);
  r.points = static_cast<std::size_t>(cloud.points.cols());
  r.dropped = cloud.dropped;
  r.read_seconds = clock.lap();
  r.scan = naming_input(scan.string(), [&] { return analyse_scanned_cam(cloud.points, so); });
  if (o.fairing) {
    ScanCamFairing f{{}, r.scan.displacement.height, {}, {}};
    if (r.nominal)
      f.acceleration_rms_before = compare_to_nominal(r.scan, *r.nominal).svaj_stats[2].rms;
    f.fairing = fair_scanned_displacement(r.scan, *o.fairing);
    r.fairing = std::move(f);
  }
  r.interrogation = interrogate_profile(r.scan.fit);
  r.resolution = resolve_motion(r.scan);
  try {
    r.design = recover_design(r.scan);
  } catch (const InputError& e) {
    r.design_failure = e.what();
  }
  if (r.nominal) {
    r.comparison =
        naming_input(scan.string(), [&] { return compare_to_nominal(r.scan, *r.nominal); });
    if (r.fairing) r.fairing->acceleration_rms_after = r.comparison->svaj_stats[2].rms;
    r.tolerance = o.tolerance;
    if (o.tolerance) r.within_tolerance = r.comparison->normal_stats.max <= *o.tolerance;
    if (const auto w = wrong_nominal_warning(r, o)) r.warnings.push_back(*w);
  }
  r.seconds = r.read_seconds + clock.lap();
  return r;
}

}  // namespace polarform
