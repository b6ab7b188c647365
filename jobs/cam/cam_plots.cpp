#include "jobs/cam/cam_plots.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "designers/cam/cam_frame.h"
#include "src/number_text.h"
#include "src/nurbs/tessellation.h"
#include "src/units.h"

namespace polarform {

namespace {

const char* kJumpColor = "#d55e00";
const char* kCamAngle = "cam angle θ [deg]";

std::vector<double> in_degrees(const std::vector<double>& radians) {
  std::vector<double> out;
  for (double x : radians) out.push_back(x * kDegreesPerRadian);
  return out;
}

// The grid angles in degrees with 360 appended, to close the revolution.
std::vector<double> closed_degrees(const std::vector<double>& radians) {
  std::vector<double> out = in_degrees(radians);
  out.push_back(360.0);
  return out;
}

void close(std::vector<double>& values) { values.push_back(values.front()); }

void cam_angle_axis(Plot& plot) {
  plot.x_label = kCamAngle;
  plot.x_range = AxisRange{0, 360};
  plot.x_tick_step = 30;
}

// Segment boundaries as grey lines (draggable: boundary k carries handle k), continuity issues
// as orange lines, labelled on the first panel only.
void mark_segments(const CamDesignStage& d, Plot& plot, bool labels, bool draggable = false) {
  const auto& segments = d.program.segments();
  for (std::size_t k = 1; k < segments.size(); ++k)
    plot.add_vertical_line(segments[k].start() * kDegreesPerRadian, {}, {},
                           draggable ? static_cast<int>(k) : -1);
  for (const ContinuityIssue& issue : d.continuity) {
    static const char* names[] = {"s", "v", "a", "j"};
    plot.add_vertical_line(issue.angle * kDegreesPerRadian,
                           labels ? std::string(names[issue.derivative]) + " jump" : "",
                           kJumpColor);
  }
}

Series series(std::string label, std::vector<double> x, std::vector<double> y,
              Series::Style style = Series::Style::line, std::string color = {}) {
  Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  s.color = std::move(color);
  return s;
}

void add_points(Plot& plot, std::string label, const std::vector<Eigen::Vector2d>& points,
                Series::Style style, std::string color = {}) {
  std::vector<double> x, y;
  for (const auto& p : points) x.push_back(p.x()), y.push_back(p.y());
  plot.add(series(std::move(label), std::move(x), std::move(y), style, std::move(color)));
}

void add_circle(Plot& plot, std::string label, double radius, Series::Style style) {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k <= 360; ++k)
    points.emplace_back(radius * std::cos(k * kRadiansPerDegree),
                        radius * std::sin(k * kRadiansPerDegree));
  add_points(plot, std::move(label), points, style, "#999999");
}

bool flat_faced(const CamDesignStage& d) {
  return std::holds_alternative<PlateCam>(d.cam) && is_flat_faced(d.project.cam.follower.kind);
}

// What matters for a flat face beside its pressure angle: where along the face the cam touches it
// (CamSample::face_contact), and the extent the face must have (the analysis's).
void show_face_contact(Plot& plot, const CamDesignStage& d, const CamAnalysisStage& a,
                       std::vector<double> x_deg, std::vector<double> contact) {
  plot.y_label = is_oscillating(d.project.cam.follower.kind)
                     ? "contact on the face from the pivot [mm]"
                     : "contact on the face [mm]";
  plot.add(series("", std::move(x_deg), std::move(contact)));
  const std::optional<FaceWidth>& width = std::get<PlateCamAnalysis>(a.cam).analysis.face_width;
  if (!width) return;
  plot.add_horizontal_line(width->right,
                           "face needs " + number_text(width->width()) + " mm, from " +
                               number_text(width->left) + " to " + number_text(width->right),
                           kJumpColor);
  plot.add_horizontal_line(width->left, "", kJumpColor);
}

}  // namespace

Figure svaj_figure(const CamDesignStage& d, const CamAnalysisStage& a, const SvajFigureOptions& o) {
  Figure f(900, o.pressure_panel ? 1160 : 960);
  f.title = "Follower motion at " + number_text(d.project.cam.rpm) + " rpm";
  f.shared_x = true;
  const MotionCurves& m = a.curves;
  const std::vector<double> x = in_degrees(m.theta);
  // At constant cam speed ω, dᵏs/dtᵏ = ωᵏ dᵏs/dθᵏ; accelerations and jerks in metres. An
  // oscillating follower's motion is the arm's swing: °/rad^k of cam angle, rad/s^k in time.
  const double w = angular_speed(d.project.cam.rpm);
  const bool arm = is_oscillating(d.project.cam.follower.kind);
  const double unit = arm ? kRadiansPerDegree : kMetresPerMillimetre;
  const double time_scale[4] = {1, w * (arm ? kRadiansPerDegree : 1.0), w * w * unit,
                                w * w * w * unit};
  const char* per_radian[2][4] = {{"s [mm]", "v [mm/rad]", "a [mm/rad²]", "j [mm/rad³]"},
                                  {"swing [°]", "v [°/rad]", "a [°/rad²]", "j [°/rad³]"}};
  const char* in_time[2][4] = {
      {"s [mm]", "v [mm/s]", "a [m/s²]", "j [m/s³]"},
      {"swing [°]", "ω arm [rad/s]", "α arm [rad/s²]", "jerk arm [rad/s³]"}};
  const std::vector<double>* values[4] = {&m.s, &m.v, &m.a, &m.j};
  for (int k = 0; k < 4; ++k) {
    const double scale = o.time_units ? time_scale[k] : 1.0;
    Plot& plot = f.add_panel();
    plot.y_label = (o.time_units ? in_time : per_radian)[arm][k];
    cam_angle_axis(plot);
    std::vector<double> y;
    for (double v : *values[k]) y.push_back(v * scale);
    plot.add(series("", x, std::move(y)));
    mark_segments(d, plot, k == 0, o.draggable_boundaries);
    for (const ContinuityIssue& issue : d.continuity) {
      if (issue.derivative != k) continue;
      // A jump at the seam shows at both ends of the revolution.
      for (double at : {issue.angle * kDegreesPerRadian, issue.angle == 0.0 ? 360.0 : -1.0}) {
        if (at < 0) continue;
        plot.add_highlight(at, issue.before_value * scale, issue.message(), kJumpColor);
        plot.add_highlight(at, issue.after_value * scale, issue.message(), kJumpColor);
      }
    }
  }
  if (o.pressure_panel && flat_faced(d)) {
    Plot& plot = f.add_panel();
    cam_angle_axis(plot);
    show_face_contact(plot, d, a, x, std::get<PlateCamAnalysis>(a.cam).curves.face_contact);
    mark_segments(d, plot, false, o.draggable_boundaries);
  } else if (o.pressure_panel) {
    Plot& plot = f.add_panel();
    plot.y_label = "pressure angle [deg]";
    cam_angle_axis(plot);
    plot.add(series("", x, in_degrees(m.pressure_angle)));
    const bool plate = std::holds_alternative<PlateCam>(d.cam);
    if (!plate) plot.title = "at the pitch radius";
    if (o.pressure_angle_limit && plate && !is_flat_faced(d.project.cam.follower.kind)) {
      const double limit = *o.pressure_angle_limit * kDegreesPerRadian;
      plot.add_horizontal_line(limit, "limit " + number_text(limit) + "°", kJumpColor);
      plot.add_horizontal_line(-limit, "", kJumpColor);
    }
    mark_segments(d, plot, false, o.draggable_boundaries);
  }
  return f;
}

Figure analysis_figure(const CamDesignStage& d, const CamAnalysisStage& a) {
  Figure f(900, 640);
  f.shared_x = true;
  const std::vector<double> x = closed_degrees(a.angles);
  Plot& pressure = f.add_panel();
  pressure.y_label = "pressure angle [deg]";
  cam_angle_axis(pressure);
  Plot& radius = f.add_panel();
  radius.y_label = "radius of curvature [mm]";
  if (const auto* p = std::get_if<PlateCamAnalysis>(&a.cam)) {
    f.title = "Pressure angle and radius of curvature";
    std::vector<double> phi, contour, pitch;
    for (const CamSample& s : p->analysis.samples) {
      phi.push_back(s.pressure_angle * kDegreesPerRadian);
      contour.push_back(s.contour_curvature != 0 ? 1 / s.contour_curvature : NAN);
      pitch.push_back(s.pitch_curvature != 0 ? 1 / s.pitch_curvature : NAN);
    }
    for (auto* v : {&phi, &contour, &pitch}) close(*v);
    if (flat_faced(d)) {
      f.title = "Contact on the face and radius of curvature";
      std::vector<double> contact;
      for (const CamSample& s : p->analysis.samples) contact.push_back(s.face_contact);
      close(contact);
      show_face_contact(pressure, d, a, x, std::move(contact));
    } else {
      pressure.add(series("", x, phi));
    }
    radius.add(series("contour", x, contour));
    const Follower& follower = d.project.cam.follower;
    if (has_roller(follower.kind)) {
      radius.add(series("pitch curve", x, pitch, Series::Style::dashed));
      radius.add_horizontal_line(follower.roller_radius, "roller radius", kJumpColor);
    }
    // Radii go to ±∞ at inflections: show the working range.
    const double limit = 4 * (d.project.cam.base_radius + d.program.stroke());
    radius.y_range = AxisRange{-limit, limit};
    for (const AngleRange& u : p->analysis.undercut)
      radius.add_band(u.from * kDegreesPerRadian, u.to * kDegreesPerRadian, "undercut", kJumpColor);
  } else {
    const auto& c = std::get<CylindricalCamAnalysis>(a.cam);
    f.title = "Pressure angle at the pitch radius";
    std::vector<double> phi = in_degrees(c.pressure_angle);
    close(phi);
    pressure.add(series("", x, phi));
    std::vector<double> z;
    for (const Kinematics& k : a.kinematics) z.push_back(d.project.cam.z0 + k.displacement);
    close(z);
    radius.y_label = "track height z [mm]";
    radius.add(series("", x, z));
  }
  if (a.pressure_angle_limit) {
    const double limit = *a.pressure_angle_limit * kDegreesPerRadian;
    pressure.add_horizontal_line(limit, "limit " + number_text(limit) + "°", kJumpColor);
    pressure.add_horizontal_line(-limit, "", kJumpColor);
  }
  mark_segments(d, pressure, true);
  mark_segments(d, radius, false);
  return f;
}

namespace {

// The oscillating follower at θ = 0 (cam and fixed frames coincide): the pivot, and the arm to the
// roller centre or the face line from the pivot's foot across the contact at (0, Rb).
void add_arm_at_rest(Plot& plot, const PlateCam& cam) {
  const Eigen::Vector2d pivot = cam.pivot();
  std::vector<Eigen::Vector2d> arm = {pivot};
  if (cam.follower().kind == FollowerKind::OscillatingRoller) {
    arm.emplace_back(0.0, cam.prime_radius());
  } else {
    const double foot_y =
        cam.base_radius();  // the face y = Rb at rest; the pivot's foot is (px, Rb)
    arm.emplace_back(pivot.x(), foot_y);
    arm.emplace_back(-0.25 * pivot.x(), foot_y);
  }
  add_points(plot, "arm at θ = 0", arm, Series::Style::line_markers, "#e69f00");
}

Figure plate_profile_figure(const CamDesignStage& d, const CamAnalysisStage& a,
                            const CamConversionStage& c, const PlateProfile& profile) {
  Figure f(800, 800);
  Plot& plot = f.add_panel();
  plot.equal_aspect = true;
  plot.x_label = "x [mm]";
  plot.y_label = "y [mm]";
  const NurbsCurve2d& curve = profile.curve;
  f.title = "Cam profile: degree " + std::to_string(curve.degree()) + ", " +
            std::to_string(curve.size()) + " control points, " +
            std::to_string(c.conversion.arcs.size()) + " arcs";
  add_points(plot, "contour (NURBS)", tessellate(curve, 2000).points, Series::Style::line,
             "#0072b2");
  add_points(plot, "control polygon", curve.control_points(), Series::Style::line_markers,
             "#cc79a7");
  if (const auto& second = c.companion)
    add_points(plot,
               second->kind == CompanionKind::GrooveOuterFlank ? "groove outer flank (NURBS)"
                                                               : "conjugate cam (NURBS)",
               tessellate(second->conversion.curve, 2000).points, Series::Style::line, "#d55e00");
  add_circle(plot, "base circle", d.project.cam.base_radius, Series::Style::dashed);
  if (has_roller(d.project.cam.follower.kind))
    add_points(plot, "pitch curve", std::get<PlateCamAnalysis>(a.cam).curves.pitch,
               Series::Style::dashed, "#009e73");
  if (is_oscillating(d.project.cam.follower.kind)) add_arm_at_rest(plot, std::get<PlateCam>(d.cam));
  return f;
}

// The track centre line on the pitch cylinder unrolled at 1:1, each point at the cam angle θ that
// brings it under the roller (cam_frame.h): θ = 0 at the left and the follower passing from left
// to right, so that the track reads like the motion program.
Figure developed_track_figure(const CamDesignStage& d, const NurbsCurve3d& track) {
  const CamDesign& cam = d.project.cam;
  std::vector<std::pair<double, double>> points;  // (θ, z)
  for (const Eigen::Vector3d& p : tessellate(track, 2000).points) {
    double theta =
        std::fmod(cam_angle(std::atan2(p.y(), p.x()), cam.rotation), 2 * std::numbers::pi);
    if (theta < 0) theta += 2 * std::numbers::pi;
    points.emplace_back(theta, p.z());
  }
  std::sort(points.begin(), points.end());
  points.emplace_back(2 * std::numbers::pi, points.front().second);
  std::vector<double> x, z;
  for (const auto& [theta, height] : points) {
    x.push_back(cam.cylinder_radius * theta);
    z.push_back(height);
  }
  // As wide as the page and as high as the track needs at 1:1, within reason.
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  const double length = 2 * std::numbers::pi * cam.cylinder_radius;
  Figure f(1000, std::clamp(190 + 900 * 1.2 * (*hi - *lo) / length, 300.0, 900.0));
  f.title = "Track centre line, developed at true aspect: degree " +
            std::to_string(track.degree()) + ", " + std::to_string(track.size()) +
            " control points";
  Plot& plot = f.add_panel();
  plot.equal_aspect = true;
  plot.x_label = "Rc·θ, the pitch cylinder developed in the direction of rotation [mm]";
  plot.y_label = "z [mm]";
  plot.add(series("track centre (NURBS)", std::move(x), std::move(z)));
  return f;
}

}  // namespace

Figure profile_figure(const CamDesignStage& d, const CamAnalysisStage& a,
                      const CamConversionStage& c) {
  if (const auto* profile = std::get_if<PlateProfile>(&c.profile))
    return plate_profile_figure(d, a, c, *profile);
  return developed_track_figure(d, std::get<CylindricalTrack>(c.profile).curve);
}

Figure conversion_error_figure(const CamConversionStage& c, bool log_scale) {
  Figure f(900, 420);
  f.title = "Measured radial error of the NURBS profile (tolerance " +
            number_text(to_micrometres(c.conversion.tolerance)) + " µm)";
  Plot& plot = f.add_panel();
  plot.x_label = "polar angle ψ [deg]";
  plot.y_label = "radial error [µm]";
  plot.x_range = AxisRange{0, 360};
  plot.x_tick_step = 30;
  plot.log_y = log_scale;
  std::vector<double> y;
  for (double e : c.error.error) y.push_back(to_micrometres(e));
  plot.add(series("|ρ − R(ψ)|", in_degrees(c.error.angle), std::move(y)));
  plot.add_horizontal_line(to_micrometres(c.conversion.tolerance), "tolerance", kJumpColor);
  for (std::size_t j = 1; j < c.conversion.arcs.size(); ++j)
    plot.add_vertical_line(degrees_in_turn(c.conversion.arcs[j].start));
  plot.add_annotation(degrees_in_turn(c.conversion.arcs.front().start),
                      to_micrometres(c.conversion.tolerance), "grey lines: arc junctions");
  return f;
}

namespace {

// One quantity of the dynamics against cam angle, with the segment boundaries; `decorate` adds
// to the plot.
// `second`: a conjugate pair's second-roller value, drawn beside the first's.
Figure dynamics_figure(const CamDesignStage& d, const CamAnalysisStage& a, const std::string& title,
                       const std::string& y_label, double DynamicsSample::*value,
                       const std::function<void(Plot&)>& decorate = {},
                       double DynamicsSample::*second = nullptr) {
  Figure f(900, 420);
  f.title = title + " at " + number_text(d.project.cam.rpm) + " rpm";
  Plot& plot = f.add_panel();
  plot.y_label = y_label;
  cam_angle_axis(plot);
  const bool pair = second && a.dynamics.value().conjugate;
  std::vector<double> x, y, y2;
  for (const DynamicsSample& s : a.dynamics.value().samples) {
    x.push_back(s.theta * kDegreesPerRadian);
    y.push_back(s.*value);
    if (pair) y2.push_back(s.*second);
  }
  if (pair) plot.add(series("second roller", x, std::move(y2), Series::Style::dashed));
  plot.add(series(pair ? "first roller" : "", std::move(x), std::move(y)));
  mark_segments(d, plot, true);
  if (decorate) decorate(plot);
  return f;
}

}  // namespace

Figure contact_force_figure(const CamDesignStage& d, const CamAnalysisStage& a) {
  const FollowerDynamics& dyn = a.dynamics.value();
  return dynamics_figure(
      d, a, "Contact force", "contact force [N]", &DynamicsSample::force,
      [&](Plot& plot) {
        plot.add_horizontal_line(0.0, dyn.jumps ? "contact lost below" : "", kJumpColor);
        if (dyn.jumps)
          plot.add_highlight(dyn.least_force.theta * kDegreesPerRadian, dyn.least_force.force,
                             "the follower jumps: " + number_text(dyn.least_force.force) + " N");
      },
      &DynamicsSample::second_force);
}

Figure camshaft_torque_figure(const CamDesignStage& d, const CamAnalysisStage& a) {
  return dynamics_figure(d, a, "Camshaft torque", "torque [N·m]", &DynamicsSample::torque);
}

Figure contact_stress_figure(const CamDesignStage& d, const CamAnalysisStage& a) {
  return dynamics_figure(d, a, "Hertz contact stress", "contact stress [MPa]",
                         &DynamicsSample::contact_stress, {}, &DynamicsSample::second_stress);
}

}  // namespace polarform
