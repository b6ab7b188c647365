#include "jobs/sweep/sweep_job.h"

#include <chrono>
#include <numbers>

#include "src/error.h"
#include "src/io/point_cloud.h"
#include "src/number_text.h"

namespace polarform {

SweepJobResult run_sweep_job(const std::filesystem::path& scan, const SweepJobOptions& o) {
  if (o.kind == SweepKind::extrusion)
    throw InputError(
        "--kind extrusion: extrusion recovery is not implemented yet (use revolution)");
  if (o.center && !o.axis) throw InputError("--center: give --axis with it");
  if (o.axis && !(o.axis->norm() > 0.0)) throw InputError("--axis: the direction is zero");
  const auto t0 = std::chrono::steady_clock::now();
  SweepJobResult r;
  r.input = scan;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  PointCloud cloud = read_point_cloud(scan, ro);
  r.points = std::move(cloud.points);
  r.dropped = cloud.dropped;
  r.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RevolutionOptions rev;
  rev.axis_direction = o.axis;
  rev.axis_point = o.center;
  rev.tolerance = o.tolerance;
  rev.degree = o.degree;
  rev.corner_angle = o.corner_angle_deg * std::numbers::pi / 180.0;
  rev.threads = o.threads;
  try {
    r.revolution = recover_revolution(r.points, rev);
  } catch (const InputError& e) {
    throw InputError(scan.string() + ": " + e.what());
  }
  const RevolutionRecovery& v = r.revolution;
  r.reason =
      std::string(o.kind == SweepKind::automatic ? "auto: revolution (the only kind implemented); "
                                                 : "revolution as asked; ") +
      "PCA tie ratio of the transverse eigenvalues " + number_text(v.tie_ratio) +
      (v.tie_ratio <= 0.1 ? " (<= 0.1: rotationally symmetric)"
                          : " (> 0.1: not symmetric by PCA)") +
      ", rms of all points " + number_text(v.error.rms) + " mm against the tolerance " +
      number_text(v.tolerance) + " mm";
  if (o.interrogate) r.interrogation = interrogate_surfaces(v.surfaces, *o.interrogate);
  r.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace polarform
