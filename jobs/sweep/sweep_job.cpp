#include "jobs/sweep/sweep_job.h"

#include <chrono>
#include <numbers>

#include "src/error.h"
#include "src/io/point_cloud.h"
#include "src/number_text.h"

namespace polarform {

namespace {

RevolutionRecovery revolution_of(const Eigen::Matrix3Xd& points, const SweepJobOptions& o) {
  RevolutionOptions rev;
  rev.axis_direction = o.axis;
  rev.axis_point = o.center;
  rev.tolerance = o.tolerance;
  rev.degree = o.degree;
  rev.corner_angle = o.corner_angle_deg * std::numbers::pi / 180.0;
  rev.threads = o.threads;
  return recover_revolution(points, rev);
}

ExtrusionRecovery extrusion_of(const Eigen::Matrix3Xd& points, const SweepJobOptions& o) {
  ExtrusionOptions ext;
  ext.direction = o.axis;
  ext.tolerance = o.tolerance;
  ext.degree = o.degree;
  ext.corner_angle = o.corner_angle_deg * std::numbers::pi / 180.0;
  ext.threads = o.threads;
  return recover_extrusion(points, ext);
}

SectionRecovery sections_of(const Eigen::Matrix3Xd& points, const SweepJobOptions& o) {
  SectionOptions sec;
  sec.tolerance = o.tolerance;
  sec.degree = o.degree;
  sec.spine = o.spine;
  if (o.sections > 0) sec.initial_sections = sec.max_sections = o.sections;
  sec.threads = o.threads;
  return recover_sections(points, sec);
}

std::string figures(const SweptFit& f) {
  return "max " + number_text(f.error.max) + " mm, rms " + number_text(f.error.rms) + " mm";
}

// Both kinds recovered: the one within the tolerance, else the one with the smaller rms; a tie
// (a cylinder is both) goes to the surface of revolution, whose circles are exact.
bool extrusion_wins(const SweptFit& rev, const SweptFit& ext) {
  const bool rev_ok = rev.error.max <= rev.tolerance, ext_ok = ext.error.max <= ext.tolerance;
  if (rev_ok != ext_ok) return ext_ok;
  if (rev_ok) return ext.error.max < 0.5 * rev.error.max;
  return ext.error.rms < rev.error.rms;
}

}  // namespace

const SweptFit& SweepJobResult::fit() const {
  if (is_sections) return *sections;
  if (is_extrusion) return *extrusion;
  return *revolution;
}

SweepJobResult run_sweep_job(const std::filesystem::path& scan, const SweepJobOptions& o) {
  if (o.center && !o.axis) throw InputError("--center: give --axis with it");
  if (o.center && o.kind == SweepKind::extrusion)
    throw InputError("--center: an extrusion has no axis point (--axis gives its direction)");
  if (o.axis && !(o.axis->norm() > 0.0)) throw InputError("--axis: the direction is zero");
  if (o.axis && o.kind == SweepKind::sections)
    throw InputError(
        "--axis: the kind sections starts from the PCA axis and bends its spine "
        "through the section centres; give no --axis");
  if (o.sections != 0 && o.kind != SweepKind::sections)
    throw InputError("--sections: only with --kind sections");
  if (o.sections < 0 || o.sections == 1)
    throw InputError("--sections " + std::to_string(o.sections) + ": expected at least 2");
  const auto t0 = std::chrono::steady_clock::now();
  SweepJobResult r;
  r.input = scan;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  PointCloud cloud = read_point_cloud(scan, ro);
  r.points = std::move(cloud.points);
  r.dropped = cloud.dropped;
  r.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  try {
    if (o.kind == SweepKind::revolution) {
      r.revolution = revolution_of(r.points, o);
      r.reason = "revolution as asked";
    } else if (o.kind == SweepKind::sections) {
      r.sections = sections_of(r.points, o);
      r.is_sections = true;
      r.reason = std::string("sections as asked: ") + std::to_string(r.sections->stations.size()) +
                 " stations along a " + (r.sections->spine_curved ? "curved" : "straight") +
                 " spine" + (o.sections > 0 ? " (the count given)" : " (adaptive slicing)");
    } else if (o.kind == SweepKind::extrusion) {
      r.extrusion = extrusion_of(r.points, o);
      r.is_extrusion = true;
      r.reason = "extrusion as asked";
    } else {
      if (r.points.cols() < 8)
        throw InputError("sweep: " + std::to_string(r.points.cols()) + " points, need at least 8");
      r.evidence = sweep_kind_evidence(r.points, 16, 20000, o.threads);
      const bool ext = r.evidence->extrusion_like(), rev = r.evidence->revolution_like();
      r.reason = "auto: " + r.evidence->text();
      if (ext && !rev) {
        r.extrusion = extrusion_of(r.points, o);
        r.is_extrusion = true;
        r.reason += "; extrusion";
      } else if (rev && !ext) {
        r.revolution = revolution_of(r.points, o);
        r.reason += "; revolution";
      } else {
        r.revolution = revolution_of(r.points, o);
        r.extrusion = extrusion_of(r.points, o);
        r.is_extrusion = extrusion_wins(*r.revolution, *r.extrusion);
        r.reason += std::string("; both recovered (revolution ") + figures(*r.revolution) +
                    ", extrusion " + figures(*r.extrusion) + "): " + r.kind() +
                    " kept (within the tolerance first, then the smaller rms; a tie is a "
                    "revolution)";
      }
    }
  } catch (const InputError& e) {
    throw InputError(scan.string() + ": " + e.what());
  }
  const SweptFit& f = r.fit();
  r.reason += ", rms of all points " + number_text(f.error.rms) + " mm against the tolerance " +
              number_text(f.tolerance) + " mm";
  if (o.interrogate) r.interrogation = interrogate_surfaces(f.surfaces, *o.interrogate);
  r.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace polarform
