// The cam job: everything `polarform cam` and the studio compute for a cam project, as a staged
// pipeline whose stages the studio runs one by one while the design is edited:
//   design   the motion program, its continuity up to jerk, the plate or cylindrical cam;
//   analyse  SVAJ on the analysis grid (time units at the cam's speed), motion curves sampled
//            segment by segment, and the plate cam's analyses (pressure angle, radii of
//            curvature, undercut) or the cylindrical cam's pressure angle at the pitch radius;
//   convert  the exact NURBS profile (plate contour or cylindrical track centre line) within the
//            tolerance, its measured radial error along the profile, the degree-limited and the
//            degree-capped profiles, the groove walls, a grooved plate cam's outer flank or a
//            conjugate cam's second contour.
// The result value is what the studio shows and what the output bundle (cam_outputs.h) writes.
// Computing writes nothing.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "designers/cam/barrel_cam.h"
#include "designers/cam/cam_analysis.h"
#include "designers/cam/continuity.h"
#include "designers/cam/follower_dynamics.h"
#include "designers/cam/groove_surface.h"
#include "designers/convert/degree_limited.h"
#include "designers/convert/polar_conversion.h"
#include "jobs/project/cam_project.h"
#include "src/error.h"

namespace polarform {

struct CamJobOptions {
  int analysis_angles = 720;  // grid of the analyses and of svaj.csv over one revolution
  int curve_samples = 720;    // samples per revolution of the motion and profile curves
  int error_samples = 4000;   // samples of the measured radial error along the profile
  int limited_degree = 3;     // degree of the degree-limited profile (profile_deg3.dxf)
  bool with_limited = true;   // compute the degree-limited profile
  // Cam angles per revolution at which a conjugate pair's centre-distance error is measured.
  int centre_distance_samples = 7200;
  // The share of the tolerance a conjugate pair's contours are first converted at.
  double conjugate_share = 0.35;
};

// ---- Stage 1: design -----------------------------------------------------------------------

struct CamDesignStage {
  CamProject project;
  CamProgram program;
  std::vector<ContinuityIssue> continuity;  // displacement up to jerk, at segment boundaries
  std::variant<PlateCam, BarrelCam> cam;
};

// Throws InputError (bad design) naming the cause.
CamDesignStage design_cam(const CamProject& project);

// ---- Stage 2: analyse ----------------------------------------------------------------------

// The motion sampled segment by segment, both ends of each segment included, so that a jump at
// a boundary shows as a jump: the curves of the SVAJ plots.
struct MotionCurves {
  std::vector<double> theta;           // cam angle, rad, non-decreasing
  std::vector<double> s, v, a, j;      // mm, mm/rad, mm/rad², mm/rad³
  std::vector<double> pressure_angle;  // rad (cylindrical cams: at the pitch radius)
};

// A plate cam's curves at the MotionCurves' angles, in the cam frame.
struct PlateCurves {
  std::vector<Eigen::Vector2d> pitch, contour;
  std::vector<Eigen::Vector2d> normal;  // unit, pointing out of the cam
  std::vector<double> curvature;        // signed contour curvature, 1/mm (> 0 convex)
  std::vector<double> face_contact;     // flat faces: CamSample::face_contact, mm
  std::vector<double> arm_lever;        // oscillating followers: CamSample::arm_lever, mm
};

struct PlateCamAnalysis {
  CamAnalysis analysis;  // extremes, and one CamSample per grid angle
  PlateCurves curves;
  // Roller followers: the roller as a pipe around the pitch curve (cam_analysis.h).
  std::optional<PitchPipeBound> pipe_bound;
};

struct CylindricalCamAnalysis {
  MotionExtrema motion;                // largest |s'|, |s''|, |s'''| and where
  std::vector<double> pressure_angle;  // at the pitch radius, at each grid angle, rad
  // The groove walls (−z side, +z side) where they cut the pitch cylinder, developed onto it:
  // (x = Rc·φ, z) in mm, from the exact roller envelope at the MotionCurves' angles.
  std::array<std::vector<Eigen::Vector2d>, 2> developed_walls;
};

// The largest |pressure angle| a design should have when its project sets none: 30° for
// translating knife-edge and roller followers and for cylindrical cams (the usual rule, e.g.
// Norton's Cam Design and Manufacturing Handbook); none for a flat-faced follower, whose pressure
// angle is fixed by its geometry.
std::optional<double> default_pressure_angle_limit(const CamDesign& cam);

struct CamAnalysisStage {
  std::vector<double> angles;          // the analysis grid, rad
  std::vector<Kinematics> kinematics;  // at each grid angle, in time at the cam's speed
  MotionCurves curves;
  std::variant<PlateCamAnalysis, CylindricalCamAnalysis> cam;  // as the design's cam
  std::optional<double> pressure_angle_limit;  // rad: the project's, or the follower's default
  std::vector<std::string> warnings;           // a pressure angle beyond the limit, a jump
  // With the project's <dynamics>, for a plate cam: force, torque, contact stress over the
  // motion curves' angles (both sides of every segment boundary).
  std::optional<FollowerDynamics> dynamics;

  // Whether the largest |pressure angle| stays within the limit (true without a limit).
  bool pressure_angle_within_limit() const;
  // The largest |pressure angle| and where (rad): the plate cam's analysis, or the cylindrical
  // cam's grid maximum.
  Extremum max_pressure_angle() const;
  const MotionExtrema& motion_extrema() const;
};

CamAnalysisStage analyse_cam(const CamDesignStage& design, const CamJobOptions& options = {});

// ---- Stage 3: convert ----------------------------------------------------------------------

// The measured radial error |ρ − R(ψ)| of the NURBS profile along it, sorted by polar angle.
struct ErrorCurve {
  std::vector<double> angle;  // ψ in [0, 2π), rad
  std::vector<double> error;  // mm
};

struct PlateProfile {
  NurbsCurve2d curve;                   // the exact-degree contour
  std::optional<LimitedCurve> limited;  // the degree-limited contour (profile_deg3.dxf)
  // When the exact degree exceeds the project's max-degree: the profile exported instead.
  std::optional<LimitedCurve> capped;
  // The curve the CAD files carry: the capped profile when there is one, else the exact one.
  const NurbsCurve2d& exported() const { return capped ? capped->curve : curve; }
};

struct CylindricalTrack {
  NurbsCurve3d curve;   // the track centre line on the pitch cylinder
  double offset = 0.0;  // the conversion is of z + offset (kept positive)
  // With a groove depth: the walls on the −z and +z side of the track, within the tolerance.
  std::vector<GrooveSurface> groove;
};

// A plate cam's second exported curve: a grooved cam's outer flank (the profile is its inner
// flank) or a conjugate cam's second contour, converted within the tolerance and measured like
// the profile.
enum class CompanionKind { GrooveOuterFlank, ConjugateContour };

// A conjugate pair's measured centre-distance error (conjugate_cam.h) and the share of ε both
// contours were converted at to keep it within ε.
struct ConjugateCentreDistance {
  double max_error = 0.0;  // mm
  double theta = 0.0;      // rad, where
  double share = 0.0;      // the contours' tolerance over ε
  int samples = 0;
};

struct CompanionCurve {
  CompanionKind kind = CompanionKind::GrooveOuterFlank;
  PolarFunction function;              // R(ψ) of the exact curve
  PolarConversion conversion;          // of function
  ErrorCurve error;                    // measured along the NURBS curve
  std::optional<LimitedCurve> capped;  // when the exact degree exceeds the project's max-degree
  std::optional<ConjugateCentreDistance> centre_distance;  // a conjugate pair's, measured
  // The curve the CAD files carry: the capped curve when there is one, else the exact one.
  const NurbsCurve2d& exported() const { return capped ? capped->curve : conversion.curve; }
};

struct CamConversionStage {
  PolarFunction profile_function;  // contour R(ψ) (plate) or track height + offset (cylindrical)
  PolarConversion conversion;      // of profile_function
  ErrorCurve error;
  std::variant<PlateProfile, CylindricalTrack> profile;  // as the design's cam
  std::optional<CompanionCurve> companion;               // a grooved or conjugate plate cam
  // What the stage left out and why (a degree-limited profile that cannot meet the tolerance).
  std::vector<std::string> warnings;

  int degree() const;          // of the exact NURBS profile or track
  int control_points() const;  // of the exact NURBS profile or track
  std::size_t knot_count() const;
};

// A conjugate pair keeps its rollers' centre distance within the tolerance ε: each contour's normal
// error moves its roller by that error over cos φ, so both contours are first converted at this
// share of ε (enough for pressure angles up to acos(2 × 0.35) = 45.6° in the worst case); then
// the pair's centre-distance error is measured (conjugate_centre_distance_error) and, while it
// exceeds ε, the share is cut in proportion and both are converted again, at most
// kMaxConjugateAttempts times.
constexpr double kConjugateToleranceShare = 0.35;  // CamJobOptions::conjugate_share default
constexpr int kMaxConjugateAttempts = 6;

// Throws InputError (a tolerance below the converter's floor, …) / NumericalError from the
// converter, or when a conjugate pair's centre distance cannot be brought within ε.
CamConversionStage convert_cam(const CamDesignStage& design, const CamJobOptions& options = {});

// ---- The whole job -------------------------------------------------------------------------

struct CamJobResult {
  CamDesignStage design;
  CamAnalysisStage analysis;
  CamConversionStage conversion;
  double seconds = 0.0;  // wall time of the three stages

  const CamProject& project() const { return design.project; }
  bool plate() const { return std::holds_alternative<PlateCam>(design.cam); }
};

// What the job converts: the plate cam's contour R(ψ), or the cylindrical cam's track height
// z(φ) + track_height_offset(design) (the converter takes positive polar functions).
PolarFunction cam_profile_function(const CamDesign& design);
double track_height_offset(const CamDesign& design);

// A plate cam whose contour the analyses show to undercut (or cusp): no profile can be made, so
// nothing is converted; the design and analysis stages say where, `reason` why (the converter's
// message).
struct InfeasibleCam {
  CamDesignStage design;
  CamAnalysisStage analysis;
  std::string reason;
};

// What run_cam_job throws for such a design: an InputError (bad input, exit 2) that carries the
// stages, so that a front end can still show and write the analyses.
class InfeasibleCamError : public InputError {
 public:
  explicit InfeasibleCamError(std::shared_ptr<const InfeasibleCam> cam)
      : InputError(cam->reason), cam_(std::move(cam)) {}
  const InfeasibleCam& cam() const { return *cam_; }

 private:
  std::shared_ptr<const InfeasibleCam> cam_;
};

// Throws InfeasibleCamError (an undercut contour), InputError (bad design, …) or NumericalError
// with a message naming the cause.
CamJobResult run_cam_job(const CamProject& project, const CamJobOptions& options = {});

}  // namespace polarform
