#include "jobs/cam/cam_job.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "designers/cam/cam_frame.h"
#include "designers/cam/contour_polar_function.h"
#include "designers/cam/plate_groove.h"
#include "designers/convert/conversion_error.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/symbolic_product.h"
#include "src/units.h"

namespace polarform {

namespace {

using Clock = std::chrono::steady_clock;

void check_tolerance(const CamProject& project) {
  if (!(project.conversion.tolerance >= kMinTolerance))
    throw InputError("conversion tolerance " + format_round_trip(project.conversion.tolerance) +
                     " mm: expected >= " + format_round_trip(kMinTolerance) + " mm");
}

// The track centre line (Rc·X, Rc·Y, z): the base circle's homogeneous rows times the factors
// (Rc, F − offset, 1), with F the converted track height (Bae 2002, eq. (B.3) in curve form).
NurbsCurve3d track_curve(const PolarConversion& c, double radius, double offset) {
  const BSpline& F = c.function.spline();
  Eigen::MatrixXd rows(3, F.size());
  rows.row(0).setConstant(radius);
  rows.row(1) = F.coefs().row(0).array() - offset;
  rows.row(2).setOnes();
  return NurbsCurve3d(product_rows(BSpline(F.degree(), F.knots(), std::move(rows)), {0, 0, 1, 2},
                                   c.base.curve().homogeneous(), {0, 1, 2, 2}));
}

// The track height z(φ) + offset as the converter's (positive) polar function, exact form kept.
PolarFunction offset_track_height(const BarrelCam& barrel, double offset) {
  PolarFunction f = barrel.track_height();
  const auto height = f.derivatives;
  f.derivatives = [height, offset](double t, int d, double* out) {
    height(t, d, out);
    out[0] += offset;
  };
  if (f.exact) {
    const BSpline& e = f.exact->spline();
    f.exact = BSplineFunction(
        BSpline(e.degree(), e.knots(), Eigen::MatrixXd(e.coefs().array() + offset)));
  }
  return f;
}

// Angles over [a, b] (ends included) at about `per_revolution` samples per 2π, at least 8.
std::vector<double> segment_angles(double a, double b, int per_revolution) {
  const int n =
      std::max(8, static_cast<int>(std::ceil((b - a) / (2 * std::numbers::pi) * per_revolution)));
  std::vector<double> t(n + 1);
  for (int i = 0; i <= n; ++i) t[i] = a + (b - a) * i / n;
  t[n] = b;
  return t;
}

// The motion and contour curves of a plate cam, one-sided at the segment boundaries.
void sample_plate(const PlateCam& cam, int per_revolution, MotionCurves& m, PlateCurves& p) {
  const auto& segments = cam.program().segments();
  for (int k = 0; k < static_cast<int>(segments.size()); ++k)
    for (double t : segment_angles(segments[k].start(), segments[k].end(), per_revolution)) {
      const CamSample c = cam.sample_in_segment(k, t);
      m.theta.push_back(t);
      m.s.push_back(c.s);
      m.v.push_back(c.v);
      m.a.push_back(c.a);
      m.j.push_back(c.j);
      m.pressure_angle.push_back(c.pressure_angle);
      Eigen::Vector2d contour[2], pitch[1];
      cam.contour_in_segment(k, t, 1, contour);
      cam.pitch(t, 0, pitch);
      // A contour single-valued about the centre has its outward normal on the side of the radius.
      Eigen::Vector2d n(-contour[1].y(), contour[1].x());
      if (n.dot(contour[0]) < 0) n = -n;
      p.contour.push_back(contour[0]);
      p.pitch.push_back(pitch[0]);
      p.normal.push_back(n.norm() > 0 ? n.normalized() : contour[0].normalized());
      p.curvature.push_back(c.contour_curvature);
      p.face_contact.push_back(c.face_contact);
      p.arm_lever.push_back(c.arm_lever);
    }
}

// The motion of a cylindrical cam, one-sided at the segment boundaries.
void sample_barrel(const BarrelCam& cam, int per_revolution, MotionCurves& m) {
  for (const MotionSegment& seg : cam.program().segments())
    for (double t : segment_angles(seg.start(), seg.end(), per_revolution)) {
      double d[4];
      seg.derivatives(t, 3, d);
      m.theta.push_back(t);
      m.s.push_back(d[0]);
      m.v.push_back(d[1]);
      m.a.push_back(d[2]);
      m.j.push_back(d[3]);
      m.pressure_angle.push_back(cam.pressure_angle(t, cam.pitch_radius()));
    }
}

// The groove walls at the pitch radius developed onto the pitch cylinder: a wall point's polar
// angle becomes the cam angle it faces, unwrapped next to the sample's θ.
std::array<std::vector<Eigen::Vector2d>, 2> developed_walls(const BarrelCam& cam,
                                                            const std::vector<double>& theta) {
  std::array<std::vector<Eigen::Vector2d>, 2> walls;
  const double rc = cam.pitch_radius(), turn = 2 * std::numbers::pi;
  for (int k = 0; k < 2; ++k)
    for (double t : theta) {
      const Eigen::Vector3d w = cam.groove_wall_point(t, rc, k == 0 ? -1 : 1);
      const double faced = cam_angle(std::atan2(w.y(), w.x()), cam.rotation());
      walls[k].emplace_back(rc * (faced + turn * std::round((t - faced) / turn)), w.z());
    }
  return walls;
}

// The measured radial error at `count` + 1 equal parameter steps, sorted by polar angle.
ErrorCurve measure_error(const PolarConversion& c, const PolarFunction& f, int count) {
  const NurbsCurve2d& curve = c.curve;
  std::vector<std::pair<double, double>> samples;
  samples.reserve(static_cast<std::size_t>(count) + 1);
  for (int k = 0; k <= count; ++k) {
    const double u = curve.front() + (curve.back() - curve.front()) * k / count;
    double psi = 0.0;
    const double e = radial_error_at(curve, f, u, c.base.angle(u), &psi);
    samples.emplace_back(radians_in_turn(psi), e);
  }
  std::sort(samples.begin(), samples.end());
  ErrorCurve out;
  for (const auto& [angle, error] : samples) {
    out.angle.push_back(angle);
    out.error.push_back(error);
  }
  return out;
}

PlateProfile plate_profile(const CamProject& project, const CamConversionStage& stage,
                           const CamJobOptions& options, std::vector<std::string>& warnings) {
  PlateProfile p{stage.conversion.curve, std::nullopt, std::nullopt};
  // The degree-limited profile is an extra: when its degree cannot reach the tolerance the exact
  // profile still stands, so the job says so instead of failing. At the exact one's tolerance (a
  // conjugate pair's is tighter), like the capped one.
  if (options.with_limited) try {
      p.limited = approximate_polar_curve(stage.profile_function, options.limited_degree,
                                          stage.conversion.tolerance);
    } catch (const NumericalError& e) {
      warnings.push_back("degree-" + std::to_string(options.limited_degree) +
                         " profile not written: " + e.what());
    }
  // The capped profile replaces the exact one in the files: at the exact one's tolerance (a
  // conjugate pair's is tighter).
  if (project.max_degree && p.curve.degree() > *project.max_degree)
    p.capped = approximate_polar_curve(stage.profile_function, *project.max_degree,
                                       stage.conversion.tolerance);
  return p;
}

// The outer flank of a grooved plate cam or the second contour of a conjugate one, if any,
// converted with `conversion` (the profile's options).
std::optional<CompanionCurve> companion_curve(const CamProject& project, const PlateCam& cam,
                                              const ConversionOptions& conversion,
                                              const CamJobOptions& options) {
  const CamDesign& d = project.cam;
  CompanionCurve c;
  if (d.conjugate) {
    c.kind = CompanionKind::ConjugateContour;
    c.function = conjugate_contour_function(cam, *d.conjugate);
  } else if (d.groove_depth > 0) {
    c.kind = CompanionKind::GrooveOuterFlank;
    c.function = groove_outer_flank_function(cam);
  } else {
    return std::nullopt;
  }
  c.conversion = convert_polar_function(c.function, conversion);
  c.error = measure_error(c.conversion, c.function, options.error_samples);
  if (project.max_degree && c.conversion.curve.degree() > *project.max_degree)
    c.capped = approximate_polar_curve(c.function, *project.max_degree, conversion.tolerance);
  return c;
}

// A conjugate pair: both contours converted at share·ε, the double roller's centre-distance error
// of the converted pair measured (conjugate_cam.h), and the share tightened until it holds <= ε.
void convert_conjugate_pair(const CamProject& project, const PlateCam& cam,
                            ConversionOptions conversion, const CamJobOptions& options,
                            CamConversionStage& c) {
  const double tolerance = project.conversion.tolerance;
  double share = std::clamp(options.conjugate_share, kMinTolerance / tolerance, 1.0);
  for (int attempt = 0;; ++attempt) {
    conversion.tolerance = share * tolerance;
    c.conversion = convert_polar_function(c.profile_function, conversion);
    c.companion = companion_curve(project, cam, conversion, options);
    const CentreDistanceError e = conjugate_centre_distance_error(
        cam, *project.cam.conjugate, c.conversion.curve, c.conversion.base,
        c.companion->conversion.curve, c.companion->conversion.base,
        options.centre_distance_samples);
    c.companion->centre_distance = ConjugateCentreDistance{e.max_error, e.theta, share, e.samples};
    if (e.max_error <= tolerance) return;
    if (attempt + 1 == kMaxConjugateAttempts)
      throw NumericalError("conjugate pair: the double roller's centre-distance error " +
                           number_text(e.max_error) + " mm at θ = " + degrees_text(e.theta) +
                           " exceeds the tolerance " + number_text(tolerance) + " mm after " +
                           std::to_string(kMaxConjugateAttempts) + " conversions (last at " +
                           number_text(share) + "·ε)");
    // The error scales about linearly with the share: aim 20 % under ε.
    share *= std::min(0.8, 0.8 * tolerance / e.max_error);
    share = std::max(share, kMinTolerance / tolerance);
  }
}

CylindricalTrack cylindrical_track(const CamProject& project, const BarrelCam& barrel,
                                   const CamConversionStage& stage, double offset) {
  const CamDesign& d = project.cam;
  CylindricalTrack t{track_curve(stage.conversion, d.cylinder_radius, offset), offset, {}};
  if (d.groove_depth > 0) {
    const GrooveOptions groove{d.cylinder_radius - d.groove_depth / 2,
                               d.cylinder_radius + d.groove_depth / 2, project.conversion.tolerance,
                               project.conversion.alpha};
    for (int side : {-1, 1}) t.groove.push_back(groove_surface(barrel, side, groove));
  }
  return t;
}

}  // namespace

double track_height_offset(const CamDesign& design) {
  // s >= 0 is measured from the lowest level, so z >= z0.
  return std::max(0.0, -design.z0) + design.cylinder_radius;
}

PolarFunction cam_profile_function(const CamDesign& design) {
  if (design.type == CamType::Plate) return cam_polar_function(make_plate_cam(design));
  return offset_track_height(make_barrel_cam(design), track_height_offset(design));
}

CamDesignStage design_cam(const CamProject& project) {
  const CamDesign& d = project.cam;
  CamProgram program = make_program(d);
  std::vector<ContinuityIssue> continuity =
      check_continuity(program, 3, 1e-9, motion_unit_symbol(d.follower.kind));
  if (d.type == CamType::Plate)
    return {project, std::move(program), std::move(continuity), make_plate_cam(d)};
  return {project, std::move(program), std::move(continuity), make_barrel_cam(d)};
}

std::optional<double> default_pressure_angle_limit(const CamDesign& cam) {
  if (is_flat_faced(cam.follower.kind)) return std::nullopt;
  return 30.0 * kRadiansPerDegree;
}

Extremum CamAnalysisStage::max_pressure_angle() const {
  if (const auto* p = std::get_if<PlateCamAnalysis>(&cam)) return p->analysis.max_pressure_angle;
  const auto& c = std::get<CylindricalCamAnalysis>(cam);
  Extremum worst;
  for (std::size_t i = 0; i < c.pressure_angle.size(); ++i)
    if (std::abs(c.pressure_angle[i]) > worst.value)
      worst = {std::abs(c.pressure_angle[i]), angles[i]};
  return worst;
}

bool CamAnalysisStage::pressure_angle_within_limit() const {
  return !pressure_angle_limit || max_pressure_angle().value <= *pressure_angle_limit;
}

const MotionExtrema& CamAnalysisStage::motion_extrema() const {
  if (const auto* p = std::get_if<PlateCamAnalysis>(&cam)) return p->analysis.motion;
  return std::get<CylindricalCamAnalysis>(cam).motion;
}

namespace {

// The follower's dynamics along the motion curves: a roller touches with its radius, a flat face
// is flat, a knife edge has no line contact (no contact stress).
// A conjugate pair's second roller also carries load: its contact on the second contour at the
// same angles (segment by segment, as sample_plate).
FollowerDynamics plate_dynamics(const CamDesignStage& design, const MotionCurves& m,
                                const PlateCurves& curves, int per_revolution) {
  const Follower& follower = design.project.cam.follower;
  FollowerLoad load = *design.project.load;
  if (follower.kind == FollowerKind::KnifeEdge) load.contact_width = 0;
  const double r1 =
      has_roller(follower.kind) ? follower.roller_radius : std::numeric_limits<double>::infinity();
  std::vector<MotionSample> motion;
  for (std::size_t i = 0; i < m.theta.size(); ++i)
    motion.push_back({m.theta[i], m.s[i], m.v[i], m.a[i],
                      curves.curvature[i] != 0 ? 1 / curves.curvature[i]
                                               : std::numeric_limits<double>::infinity(),
                      curves.arm_lever[i]});
  const auto& conjugate = design.project.cam.conjugate;
  if (!conjugate) return follower_dynamics(motion, design.project.cam.rpm, r1, load);
  const auto& cam = std::get<PlateCam>(design.cam);
  const RollerImage second = conjugate_roller(cam, *conjugate);
  const auto& segments = cam.program().segments();
  std::size_t i = 0;
  for (int k = 0; k < static_cast<int>(segments.size()); ++k)
    for (double t : segment_angles(segments[k].start(), segments[k].end(), per_revolution)) {
      const SecondContact c = conjugate_contact(cam, second, k, t);
      motion.at(i).second_contour_radius = c.contour_radius;
      motion.at(i++).second_lever = c.lever;
    }
  return follower_dynamics(motion, design.project.cam.rpm, r1, load,
                           second_roller_radius(cam, *conjugate));
}

}  // namespace

CamAnalysisStage analyse_cam(const CamDesignStage& design, const CamJobOptions& options) {
  CamAnalysisStage a;
  a.angles = uniform_angles(options.analysis_angles);
  for (double theta : a.angles)
    a.kinematics.push_back(design.program.kinematics(theta, design.project.cam.rpm));
  if (const auto* plate = std::get_if<PlateCam>(&design.cam)) {
    PlateCamAnalysis p{analyse(*plate, a.angles), {}, {}};
    if (has_roller(plate->follower().kind)) p.pipe_bound = pitch_pipe_bound(*plate);
    sample_plate(*plate, options.curve_samples, a.curves, p.curves);
    if (design.project.load)
      a.dynamics = plate_dynamics(design, a.curves, p.curves, options.curve_samples);
    a.cam = std::move(p);
  } else {
    const auto& barrel = std::get<BarrelCam>(design.cam);
    CylindricalCamAnalysis c{motion_extrema(design.program, a.angles), {}, {}};
    for (double theta : a.angles)
      c.pressure_angle.push_back(barrel.pressure_angle(theta, barrel.pitch_radius()));
    sample_barrel(barrel, options.curve_samples, a.curves);
    c.developed_walls = developed_walls(barrel, a.curves.theta);
    a.cam = std::move(c);
  }
  a.pressure_angle_limit = design.project.pressure_angle_limit
                               ? design.project.pressure_angle_limit
                               : default_pressure_angle_limit(design.project.cam);
  const Extremum worst = a.max_pressure_angle();
  if (!a.pressure_angle_within_limit())
    a.warnings.push_back(
        "max pressure angle " + degrees_text(worst.value) + " at θ = " + degrees_text(worst.theta) +
        " exceeds the limit " + degrees_text(*a.pressure_angle_limit) +
        (is_oscillating(design.project.cam.follower.kind)
             ? ": increase the base radius, lengthen the segment or move the pivot "
               "(pivot-distance, arm-length, pivot-side)"
             : ": increase the base radius, lengthen the segment or offset the follower"));
  if (a.dynamics && a.dynamics->jumps)
    a.warnings.push_back("the follower jumps: the contact force falls to " +
                         number_text(a.dynamics->least_force.force) +
                         " N at θ = " + degrees_text(a.dynamics->least_force.theta) +
                         "; a spring rate of at least " + number_text(a.dynamics->min_spring_rate) +
                         " N/mm (same preload) keeps contact at " +
                         number_text(design.project.cam.rpm) + " rpm");
  return a;
}

int CamConversionStage::degree() const {
  return std::visit([](const auto& p) { return p.curve.degree(); }, profile);
}

int CamConversionStage::control_points() const {
  return std::visit([](const auto& p) { return p.curve.size(); }, profile);
}

std::size_t CamConversionStage::knot_count() const {
  return std::visit([](const auto& p) { return p.curve.knots().size(); }, profile);
}

CamConversionStage convert_cam(const CamDesignStage& design, const CamJobOptions& options) {
  const CamProject& project = design.project;
  check_tolerance(project);
  CamConversionStage c;
  if (const auto* plate = std::get_if<PlateCam>(&design.cam)) {
    c.profile_function = cam_polar_function(*plate);
    // The profile is exported as converted and made compact (the project's compaction: by
    // default refitted, one smooth curve with the fewest control points).
    const ConversionOptions& conversion = project.conversion;
    if (project.cam.conjugate) {
      convert_conjugate_pair(project, *plate, conversion, options, c);
    } else {
      c.conversion = convert_polar_function(c.profile_function, conversion);
      c.companion = companion_curve(project, *plate, conversion, options);
    }
    c.profile = plate_profile(project, c, options, c.warnings);
  } else {
    const auto& barrel = std::get<BarrelCam>(design.cam);
    const double offset = track_height_offset(project.cam);
    c.profile_function = offset_track_height(barrel, offset);
    // The track is built from F and the base circle apart (track_curve): C stays F·B.
    ConversionOptions conversion = project.conversion;
    conversion.compaction = Compaction::none;
    c.conversion = convert_polar_function(c.profile_function, conversion);
    c.profile = cylindrical_track(project, barrel, c, offset);
  }
  c.error = measure_error(c.conversion, c.profile_function, options.error_samples);
  return c;
}

CamJobResult run_cam_job(const CamProject& project, const CamJobOptions& options) {
  const auto start = Clock::now();
  check_tolerance(project);  // before the work of the first stages
  CamDesignStage design = design_cam(project);
  CamAnalysisStage analysis = analyse_cam(design, options);
  std::optional<CamConversionStage> conversion;
  try {
    conversion = convert_cam(design, options);
  } catch (const InputError& e) {
    const auto* plate = std::get_if<PlateCamAnalysis>(&analysis.cam);
    if (!plate || plate->analysis.undercut.empty()) throw;
    throw InfeasibleCamError(std::make_shared<const InfeasibleCam>(
        InfeasibleCam{std::move(design), std::move(analysis), e.what()}));
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return {std::move(design), std::move(analysis), std::move(*conversion), seconds};
}

}  // namespace polarform
