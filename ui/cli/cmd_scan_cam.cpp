// `polarform scan-cam`: inspect a manufactured plate cam or recover a lost design from a 2D profile
// scan or a 3D scan (Bae 2002, ch. 2 and §5.3): fit the polar NURBS profile, recover the follower
// displacement and its SVAJ, and compare with the nominal design when one is given.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <numbers>

#include "jobs/scan_cam/scan_cam_design_report.h"
#include "jobs/scan_cam/scan_cam_outputs.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/cli/commands.h"
#include "ui/cli/fairing_arguments.h"
#include "ui/cli/fit_arguments.h"
#include "ui/cli/progress_bar.h"

namespace polarform::cli {

namespace {

struct ScanCamArgs {
  std::string scan, out, center, bore, axis = "auto", nominal, tol, follower, roller_radius, offset,
                                       rotation, threads = "2", write_project, fair, fair_tol,
                                       fair_passes;
  bool skip_bad = false, quiet = false, lenient = false;
};

ScanCamJobOptions job_options(const ScanCamArgs& a) {
  ScanCamJobOptions o;
  if (!a.center.empty()) {
    const std::vector<double> c = parse_numbers("--center", a.center, 2, 3);
    o.center = Eigen::Vector3d(c[0], c[1], c.size() == 3 ? c[2] : 0.0);
  }
  if (a.axis != "auto") {
    const std::vector<double> k = parse_numbers("--axis", a.axis, 3, 3);
    o.axis = Eigen::Vector3d(k[0], k[1], k[2]);
    if (!(o.axis->norm() > 0))
      throw InputError("--axis '" + a.axis + "': expected a non-zero vector");
  }
  if (!a.nominal.empty()) o.nominal = a.nominal;
  o.nominal_names = unknown_names_policy(a.lenient);
  if (!a.tol.empty()) o.tolerance = parse_numbers("--tol", a.tol, 1, 1)[0];
  const bool follower_given = !a.follower.empty() || !a.roller_radius.empty() || !a.offset.empty();
  if (follower_given) {
    constexpr FollowerKind kinds[] = {FollowerKind::KnifeEdge, FollowerKind::Roller,
                                      FollowerKind::FlatFaced};
    Follower f{FollowerKind::KnifeEdge, 0.0, 0.0};
    if (!a.follower.empty())
      f.kind =
          kinds[parse_choice("--follower", a.follower, {"knife-edge", "roller", "flat-faced"})];
    if (!a.roller_radius.empty()) {
      if (f.kind != FollowerKind::Roller)
        throw InputError("--roller-radius needs --follower roller");
      f.roller_radius = parse_numbers("--roller-radius", a.roller_radius, 1, 1)[0];
    }
    if (!a.offset.empty()) f.offset = parse_numbers("--offset", a.offset, 1, 1)[0];
    o.follower = f;
  }
  if (!a.rotation.empty())
    o.rotation = parse_choice("--rotation", a.rotation, {"ccw", "cw"}) == 0
                     ? Rotation::CounterClockwise
                     : Rotation::Clockwise;
  o.threads = parse_int_pair("--threads", a.threads, 1, 256).first;
  o.skip_bad = a.skip_bad;
  o.fairing = fairing_options(a.fair, a.fair_tol, a.fair_passes);
  return o;
}

// The resolution and the recovered design: one line per rise or return.
void print_design(const ScanCamJobResult& r) {
  const MotionResolution& res = r.resolution;
  std::printf(
      "resolution: the scan resolves %s%s\n",
      res.resolved_order >= 0 ? kDerivativeNames[res.resolved_order] : "nothing",
      res.resolved_order >= 0 && res.resolved_order < 3 ? " (higher derivatives are noise)" : "");
  if (!r.design) {
    std::printf("design: not recovered: %s\n", r.design_failure.c_str());
    return;
  }
  const RecoveredDesign& d = *r.design;
  std::printf("design: %zu motions, base radius %.4f mm, phase %.4f deg\n", d.motions.size(),
              d.design.base_radius, d.phase * kDegreesPerRadian);
  for (const IdentifiedMotion& m : d.motions) {
    const LawFit& f = m.law();
    std::printf("  %s %s: lift %.4f ± %.2g mm, from %.3f ± %.2g to %.3f ± %.2g deg%s\n",
                std::string(segment_kind_name(m.kind)).c_str(), law_label(f.shape).c_str(),
                std::abs(f.lift), f.sd[3],
                std::fmod(std::fmod((f.start - d.phase) * kDegreesPerRadian, 360.0) + 360.0, 360.0),
                f.sd[0] * kDegreesPerRadian,
                std::fmod(std::fmod((f.end - d.phase) * kDegreesPerRadian, 360.0) + 360.0, 360.0),
                f.sd[1] * kDegreesPerRadian,
                m.indistinguishable.empty() ? "" : " (other laws fit as well)");
  }
  std::printf("re-designed profile against the scan (normal): rms %.3g mm, max %.3g mm\n",
              d.deviation.normal_stats.rms, d.deviation.normal_stats.max);
}

// The summary on stdout, unless --quiet.
void print_summary(const ScanCamArgs& a, const ScanCamJobResult& r,
                   const std::vector<std::string>& files) {
  if (a.quiet) return;
  const ScannedCam& s = r.scan;
  std::printf("%s scan, %ld contour points; centre: %s\n", s.profile.three_d ? "3D" : "2D",
              static_cast<long>(s.contour.cols()), s.profile.centre_reason.c_str());
  std::printf("profile: degree %d, %d control points, rms %.3g mm; noise floor %.3g mm\n",
              s.fit.curve.degree(), s.fit.curve.size(), s.fit.report.error.rms, s.contour_noise);
  std::printf(
      "displacement: degree %d, %.1f effective parameters (GCV), sample noise %.3g mm, "
      "standard error of s %.3g mm; base radius %.4f mm\n",
      s.displacement.height.degree(), s.displacement.dof, s.displacement.noise,
      s.displacement.standard_error, s.base_radius);
  if (s.alignment)
    std::printf("phase to nominal %.4f deg%s\n", s.alignment->phase * kDegreesPerRadian,
                s.mirrored ? " (mirrored)" : "");
  if (r.comparison)
    std::printf(
        "deviation from nominal (normal): rms %.3g mm, max %.3g mm; s difference rms %.3g "
        "mm, max %.3g mm\n",
        r.comparison->normal_stats.rms, r.comparison->normal_stats.max,
        r.comparison->svaj_stats[0].rms, r.comparison->svaj_stats[0].max);
  if (r.tolerance)
    std::printf("tolerance ±%.3g mm: %s\n", *r.tolerance, r.within_tolerance ? "met" : "NOT MET");
  print_design(r);
  if (!a.write_project.empty())
    std::printf("wrote the recovered design to %s\n", a.write_project.c_str());
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds * 1e3);
  std::fflush(stdout);
}

void run(const ScanCamArgs& a) {
  ScanCamJobOptions o = job_options(a);
  ProgressBar reading("reading ", !a.quiet);
  o.read_progress = [&reading](double f) {
    reading(f);
    if (f >= 1.0) reading.finish();
  };
  const ScanCamJobResult r = run_scan_cam_job(a.scan, o);
  const std::vector<std::string> files = write_scan_cam_outputs(r, a.out, a.write_project);
  for (const std::string& w : r.warnings) std::cerr << "polarform: warning: " << w << "\n";
  if (r.dropped > 0)
    std::cerr << "polarform: warning: " << r.dropped << " bad records skipped in " << a.scan
              << "\n";
  print_summary(a, r, files);
  if (r.tolerance && !r.within_tolerance)
    throw OutOfTolerance("out of tolerance: the profile deviates from the nominal by up to " +
                         number_text(r.comparison->normal_stats.max) +
                         " mm, beyond the tolerance ±" + number_text(*r.tolerance) +
                         " mm (exit status 3)");
}

}  // namespace

void add_scan_cam_command(CLI::App& app) {
  auto args = std::make_shared<ScanCamArgs>();
  CLI::App* cmd = app.add_subcommand(
      "scan-cam",
      "Inspect a manufactured plate cam or recover a lost design from a scan: a 2D profile scan\n"
      "(CMM or optical, a planar cloud) or a 3D scan of the plate (sliced at mid-thickness).\n"
      "Fits the closed polar NURBS profile about the centre of rotation, recovers the follower\n"
      "displacement s(θ) and its derivatives (smoothed by generalized cross-validation, noise "
      "floor\n"
      "stated), and with --nominal aligns the phase and reports the deviation from the design.\n"
      "States up to which derivative (s, v, a, j) the scan resolves the motion, and recovers the\n"
      "design: dwells, rises and returns, each with its law (six standard laws and SCCA, chosen\n"
      "by BIC), boundaries and lift with uncertainties; --write-project writes it as a project.\n"
      "Writes profile.igs/.stp/.dxf/.x3d (cam frame), svaj.csv, svaj.svg, deviation.svg,\n"
      "profile.svg, report.json and report.html; with a nominal also deviation.csv and\n"
      "svaj_difference.svg.");
  cmd->add_option("scan", args->scan, "point-cloud file (xyz/csv, PLY, STL, OBJ, OFF)")->required();
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  auto* center = cmd->add_option("--center", args->center,
                                 "X,Y[,Z]: a point on the cam's axis, in mm (default: the bore's "
                                 "centre)");
  cmd->add_option("--bore", args->bore, "auto: take the centre of rotation from the bore (default)")
      ->check(CLI::IsMember({"auto"}))
      ->excludes(center);
  cmd->add_option("--axis", args->axis,
                  "auto|X,Y,Z: the cam's axis (auto: normal of a 2D scan's plane, or the common "
                  "normal of a 3D scan's faces)");
  cmd->add_option("--nominal", args->nominal,
                  "cam project file (XML) of the design: its follower and rotation are used, the "
                  "phase is aligned to it and the deviation reported")
      ->check(CLI::ExistingFile);
  cmd->add_option("--tol", args->tol,
                  "MM: tolerance band of the profile about the nominal (needs --nominal); the "
                  "report says whether the normal deviation stays within ±MM, and the exit status "
                  "is 3 when it does not");
  cmd->add_option("--follower", args->follower,
                  "knife-edge|roller|flat-faced: the follower that reads s(θ) without a nominal "
                  "(default knife-edge)");
  cmd->add_option("--roller-radius", args->roller_radius, "MM: roller radius (--follower roller)");
  cmd->add_option("--offset", args->offset, "MM: follower offset e (default 0)");
  cmd->add_option("--rotation", args->rotation, "ccw|cw: sense of rotation without a nominal");
  cmd->add_option("--write-project", args->write_project,
                  "DESIGN.xml: write the design recovered from the scan (segments, laws, base "
                  "radius, follower) as a cam project; `polarform cam DESIGN.xml` reproduces the "
                  "profile to the deviation report.json states (design.redesign_deviation)");
  cmd->add_option("--fair", args->fair,
                  "farin|kjellander: fair the recovered displacement s(θ) before the motion is "
                  "compared and recovered (MIT §8.2.3); farin first refits s along the design "
                  "recovered from the scan (constant dwells, the laws' continuity at their "
                  "boundaries, smoothed to the noise by the discrepancy principle), then fairs its "
                  "knots; fairing.svg shows the acceleration before and after (Kjellander needs a "
                  "cubic s and is refused on the quintic)");
  cmd->add_option("--fair-tol", args->fair_tol,
                  "how far fairing may move s [mm] (default 3 × the displacement fit's noise)");
  cmd->add_option("--fair-passes", args->fair_passes,
                  "at most this many knots faired (default 100)");
  cmd->add_option("--threads", args->threads, "worker threads (default 2)");
  cmd->add_flag("--skip-bad", args->skip_bad,
                "skip unparsable or non-finite records instead of stopping");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress bar and no summary");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
