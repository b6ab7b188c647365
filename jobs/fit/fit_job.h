// The fit job: what `polarform fit` (and the studio) computes for a scanned point cloud — read it,
// decide the method (a planar cloud is a profile: polar curve fitting, Bae 2002 ch. 2; otherwise
// the best-fit quadric chooses spherical or cylindrical surface fitting, ch. 3 and §4.3), fit, and
// keep the measured point-to-geometry error of every input point. Computing writes nothing.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "designers/scan/cloud_plane.h"
#include "jobs/project/fit_project.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/rotational_fit.h"

namespace polarform {

struct FitJobOptions {
  FitJobMethod method = FitJobMethod::automatic;
  Closure closure = Closure::automatic;
  std::optional<PoleTreatment> pole;          // both poles of a spherical fit; else automatic
  std::optional<std::pair<int, int>> degree;  // of F: (u ↔ φ or z, v ↔ θ); curves use v
  std::optional<std::pair<int, int>> ctrl;    // F's control net, as degree
  std::optional<double> tolerance;            // mm, instead of ctrl: refine until met
  ToleranceMeasure measure = ToleranceMeasure::max;
  std::optional<Eigen::Vector3d> center;  // frame origin / polar centre (projected)
  std::optional<Eigen::Vector3d> axis;    // frame k / normal of a profile's plane
  bool skip_bad = false;
  FairnessOptions::Mode fairness = FairnessOptions::Mode::relative;  // how λ is chosen
  double fairness_weight = 1e-7;  // λ (fixed) or its scale-free weight (relative); gcv: unused
  ArcKind base = ArcKind::rqb;    // the base circles' arcs
  int threads = 2;
  ProgressFn read_progress;  // fraction of the file read
  ProgressFn fit_progress;   // fraction of the fit done (restarts when auto tries a second method)
};

struct FitJobResult {
  std::filesystem::path input;
  Eigen::Matrix3Xd points;  // as read (bad records dropped with skip_bad)
  std::size_t dropped = 0;
  std::string method;                  // "polar", "spherical" or "cylindrical"
  std::string reason;                  // why that method
  CloudPlane plane;                    // best-fit plane of the cloud (the profile plane when polar)
  std::optional<PolarCurveFit> polar;  // in plane coordinates
  std::optional<NurbsCurve3d> curve;   // the polar curve placed back in space
  std::optional<RotationalFit> surface;
  FairnessOptions::Mode fairness = FairnessOptions::Mode::relative;  // as asked
  double fairness_weight = 1e-7;
  ArcKind base = ArcKind::rqb;
  double seconds = 0.0;  // read + fit

  const FitReport& report() const { return polar ? polar->report : surface->report(); }
};

// The options a fit project asks for (progress callbacks and threads left at their defaults).
FitJobOptions fit_job_options(const FitProject& project);

// Throws InputError (unreadable or bad file, bad options, data the method cannot fit) or
// NumericalError (a tolerance that cannot be met) with a message naming the cause.
FitJobResult run_fit_job(const std::filesystem::path& scan, const FitJobOptions& options = {});

// The same on a cloud already in memory (`name` is reported as the input).
FitJobResult run_fit_job(Eigen::Matrix3Xd points, const std::string& name,
                         const FitJobOptions& options = {});

}  // namespace polarform
