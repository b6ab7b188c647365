// The scan-cam job: what `polarform scan-cam` computes to inspect a manufactured plate cam or to
// recover a lost design from a 2D profile scan or a 3D scan — read the scan (and the nominal cam
// project when given), run the scanned-cam pipeline (designers/scan/scanned_cam.h), compare it
// with the nominal, state how far the scan resolves the motion and recover the design (segments,
// laws) from it. Computing writes nothing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "designers/scan/design_recovery.h"
#include "designers/scan/displacement_fairing.h"
#include "designers/scan/motion_resolution.h"
#include "designers/scan/nominal_comparison.h"
#include "designers/scan/scanned_cam.h"
#include "jobs/fit/profile_interrogation.h"
#include "jobs/project/cam_project.h"
#include "src/fit/parallel.h"

namespace polarform {

struct ScanCamJobOptions {
  std::optional<Eigen::Vector3d> center;         // a point on the axis (X, Y, 0 for a 2D centre)
  std::optional<Eigen::Vector3d> axis;           // estimated when absent
  std::optional<std::filesystem::path> nominal;  // cam project (XML)
  UnknownNames nominal_names = UnknownNames::refuse;  // the nominal's unknown names
  std::optional<double> tolerance;               // mm: profile tolerance band about the nominal
  // The follower that reads the displacement when there is no nominal (the nominal's otherwise).
  std::optional<Follower> follower;
  std::optional<Rotation> rotation;
  bool skip_bad = false;
  int threads = 2;
  ProgressFn read_progress;
  // Fair the recovered displacement s(θ) before anything uses it (displacement_fairing.h).
  std::optional<ProfileFairingOptions> fairing;
};

// What --fair did to s(θ), and (with a nominal) the rms error of the recovered acceleration
// against the nominal's before and after it, mm/rad².
struct ScanCamFairing {
  DisplacementFairing fairing;
  BSplineFunction before;  // y0 + s(θ) as fitted
  std::optional<double> acceleration_rms_before, acceleration_rms_after;
};

struct ScanCamJobResult {
  std::filesystem::path input;
  std::size_t points = 0, dropped = 0;
  std::filesystem::path nominal_file;  // empty without a nominal
  std::optional<CamProject> nominal_project;
  std::optional<PlateCam> nominal;
  std::vector<std::string> warnings;  // from reading the nominal project
  ScannedCam scan;
  ProfileInterrogation interrogation;  // of scan.fit.curve: curvature.svg/.csv, report.json
  std::optional<NominalComparison> comparison;
  std::optional<double> tolerance;
  bool within_tolerance = true;  // the profile's normal deviation within ±tolerance
  std::string follower_source;   // "nominal design" or "options"
  // The design recovered from the motion (segments, laws, the re-designed cam's deviation), or
  // why there is none (design_failure).
  std::optional<RecoveredDesign> design;
  std::string design_failure;
  MotionResolution resolution;  // up to which derivative the scan resolves the motion
  std::optional<ScanCamFairing> fairing;
  double read_seconds = 0.0, seconds = 0.0;
};

// Throws InputError for a bad scan, nominal project, or option combination (follower options
// with a nominal, a tolerance without one, a cylindrical nominal) or what the pipeline refuses.
ScanCamJobResult run_scan_cam_job(const std::filesystem::path& scan,
                                  const ScanCamJobOptions& options = {});

}  // namespace polarform
