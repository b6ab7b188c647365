// The fit job: what `polarform fit` and the studio compute for a scanned point cloud, as a staged
// pipeline — read it; preview what decides the method (a planar cloud is a profile: polar curve
// fitting, Bae 2002 ch. 2; otherwise the best-fit quadric chooses spherical or cylindrical surface
// fitting, ch. 3 and §4.3); fit, keeping the measured point-to-geometry error of every input
// point. The result value is what the studio shows and what the output bundle writes. Computing
// writes nothing.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "designers/scan/cloud_plane.h"
#include "jobs/fit/profile_interrogation.h"
#include "jobs/interrogation/surface_interrogation.h"
#include "jobs/project/fit_project.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/profile_fairing.h"
#include "src/fit/rotational_fit.h"
#include "src/fit/surface_fairing.h"

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
  // Leave outliers out of the fit (trimmed least squares at 8 robust σ) instead of refusing a
  // cloud with a few (src/fit/outliers.h).
  bool reject_outliers = false;
  FairnessOptions::Mode fairness = FairnessOptions::Mode::relative;  // how λ is chosen
  double fairness_weight = 1e-7;  // λ (fixed) or its scale-free weight (relative); gcv: unused
  ArcKind base = ArcKind::rqb;    // the base circles' arcs
  RevolutionMode revolution =
      RevolutionMode::automatic;  // F constant around the axis: test / force
  // Fair F after the fit (MIT §8.2.3–8.2.4), a profile's or a surface's (rows and columns of its
  // net); the geometry's move and new error are measured.
  std::optional<ProfileFairingOptions> fairing;
  // Surfaces: curvature maps and reflection lines (MIT §8.2.4) of the fitted surface and caps.
  std::optional<CurvatureQuantity> interrogate;
  int threads = 2;
  ProgressFn read_progress;  // fraction of the file read
  ProgressFn fit_progress;   // fraction of the fit done (restarts when auto tries a second method)
};

// Stage 1: the scan as read (bad records dropped with skip_bad).
struct FitInput {
  std::filesystem::path file;  // the scan, or the name of a cloud given in memory
  Eigen::Matrix3Xd points;
  std::size_t dropped = 0;
  double read_seconds = 0.0;
};

// Stage 2: what decides the method before anything is fitted — the cloud's best-fit plane (a
// planar cloud is a profile: polar curve fitting) and, for a cloud that is not planar, the local
// frame the surface fits start from (Bae 2002, §4.3), or why there is none.
struct FitPreview {
  CloudPlane plane;
  bool profile = false;                // the polar method will run
  std::optional<FrameEstimate> frame;  // surfaces: the estimated (or given) frame and quadric
  std::string frame_error;             // surfaces: why no frame could be estimated
};

// A polar profile fit: the curve in the profile plane's coordinates, and placed back in space.
struct ProfileFit {
  PolarCurveFit polar;
  NurbsCurve3d curve;
  ProfileInterrogation interrogation;  // of polar.curve: curvature.svg/.csv, report.json
  std::optional<ProfileFairing> fairing;               // when asked: what it did
  std::optional<ProfileInterrogation> before_fairing;  // the curve as fitted, before fairing
};

// Stage 3: the fit and the measured point-to-geometry error of every input point.
struct FitJobResult {
  std::filesystem::path input;
  Eigen::Matrix3Xd points;  // as read (bad records dropped with skip_bad)
  std::size_t dropped = 0;
  std::string method;  // "polar", "spherical" or "cylindrical"
  std::string reason;  // why that method
  CloudPlane plane;    // best-fit plane of the cloud (the profile plane when polar)
  std::variant<ProfileFit, RotationalFit> fit;
  FairnessOptions::Mode fairness = FairnessOptions::Mode::relative;  // as asked
  double fairness_weight = 1e-7;
  ArcKind base = ArcKind::rqb;
  bool reject_outliers = false;       // as asked; what was left out: report().outliers
  std::vector<std::string> warnings;  // about the fit: a pole that creases or is extrapolated
  double seconds = 0.0;  // read + fit
  std::optional<SurfaceInterrogation> interrogation;  // surfaces, when asked
  std::optional<SurfaceFitFairing> surface_fairing;   // surfaces, when asked

  bool profile() const { return std::holds_alternative<ProfileFit>(fit); }
  const FitReport& report() const;
};

// The options a fit project asks for (progress callbacks and threads left at their defaults).
FitJobOptions fit_job_options(const FitProject& project);

// Throws InputError for an unreadable or bad file.
FitInput read_fit_input(const std::filesystem::path& scan, const FitJobOptions& options = {});

// Throws InputError for bad options or a cloud the plane cannot be fitted to; a frame that cannot
// be estimated is reported in frame_error.
FitPreview preview_fit(const FitInput& input, const FitJobOptions& options = {});

// Throws InputError (bad options, data the method cannot fit) or NumericalError (a tolerance that
// cannot be met) with a message naming the cause.
FitJobResult fit_cloud(FitInput input, const FitJobOptions& options = {});

// All stages: read_fit_input, then fit_cloud.
FitJobResult run_fit_job(const std::filesystem::path& scan, const FitJobOptions& options = {});

// fit_cloud on a cloud already in memory (`name` is reported as the input).
FitJobResult run_fit_job(Eigen::Matrix3Xd points, const std::string& name,
                         const FitJobOptions& options = {});

}  // namespace polarform
