#include "jobs/scan_cam/scan_cam_job.h"

#include "src/error.h"
#include "src/fit/stage_times.h"
#include "src/io/point_cloud.h"

namespace polarform {

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
    r.nominal_project = read_cam_project(*o.nominal, r.warnings);
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
  if (r.nominal) {
    r.comparison =
        naming_input(scan.string(), [&] { return compare_to_nominal(r.scan, *r.nominal); });
    r.tolerance = o.tolerance;
    if (o.tolerance) r.within_tolerance = r.comparison->normal_stats.max <= *o.tolerance;
  }
  r.seconds = r.read_seconds + clock.lap();
  return r;
}

}  // namespace polarform
