#include "jobs/cam/cam_plots.h"

#include <cmath>
#include <numbers>

#include "designers/convert/conversion_error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

const char* kJumpColor = "#d55e00";

std::vector<double> in_degrees(const std::vector<double>& radians) {
  std::vector<double> out;
  for (double x : radians) out.push_back(x * kDegreesPerRadian);
  out.push_back(360.0);  // close the revolution
  return out;
}

// Segment boundaries as grey lines, continuity violations as labelled orange lines.
void mark_segments(const CamJobResult& r, Plot& plot, bool labels) {
  for (std::size_t k = 1; k < r.program.segments().size(); ++k)
    plot.add_vertical_line(r.program.segments()[k].start() * kDegreesPerRadian);
  for (const ContinuityIssue& issue : r.continuity) {
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

std::vector<Eigen::Vector2d> sample_curve(const NurbsCurve2d& c, int count) {
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k <= count; ++k) out.push_back(c(c.front() + (c.back() - c.front()) * k / count));
  return out;
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
    points.emplace_back(radius * std::cos(k / kDegreesPerRadian),
                        radius * std::sin(k / kDegreesPerRadian));
  add_points(plot, std::move(label), points, style, "#999999");
}

}  // namespace

Figure svaj_figure(const CamJobResult& r) {
  Figure f(900, 960);
  f.title = "Follower motion at " + std::to_string(static_cast<int>(std::lround(r.project.cam.rpm))) +
            " rpm";
  f.shared_x = true;
  const std::vector<double> x = in_degrees(r.angles);
  struct Panel {
    const char* label;
    double scale;
    double Kinematics::*field;
  };
  const Panel panels[] = {{"s [mm]", 1.0, &Kinematics::displacement},
                          {"v [mm/s]", 1.0, &Kinematics::velocity},
                          {"a [m/s²]", 1e-3, &Kinematics::acceleration},
                          {"j [m/s³]", 1e-3, &Kinematics::jerk}};
  for (const Panel& p : panels) {
    Plot& plot = f.add_panel();
    plot.y_label = p.label;
    plot.x_label = "cam angle θ [deg]";
    plot.x_tick_step = 30;
    std::vector<double> y;
    for (const Kinematics& k : r.kinematics) y.push_back(k.*p.field * p.scale);
    y.push_back(y.front());
    plot.add(series("", x, std::move(y)));
    mark_segments(r, plot, &p == &panels[0]);
  }
  return f;
}

Figure analysis_figure(const CamJobResult& r) {
  Figure f(900, 640);
  f.shared_x = true;
  const std::vector<double> x = in_degrees(r.angles);
  Plot& pressure = f.add_panel();
  pressure.y_label = "pressure angle [deg]";
  pressure.x_label = "cam angle θ [deg]";
  pressure.x_tick_step = 30;
  Plot& radius = f.add_panel();
  radius.y_label = "radius of curvature [mm]";
  if (r.analysis) {
    f.title = "Pressure angle and radius of curvature";
    std::vector<double> phi, contour, pitch;
    for (const CamSample& s : r.analysis->samples) {
      phi.push_back(s.pressure_angle * kDegreesPerRadian);
      contour.push_back(s.contour_curvature != 0 ? 1 / s.contour_curvature : NAN);
      pitch.push_back(s.pitch_curvature != 0 ? 1 / s.pitch_curvature : NAN);
    }
    for (auto* v : {&phi, &contour, &pitch}) v->push_back(v->front());
    pressure.add(series("", x, phi));
    radius.add(series("contour", x, contour));
    if (r.project.cam.follower.kind == FollowerKind::Roller) {
      radius.add(series("pitch curve", x, pitch, Series::Style::dashed));
      radius.add_horizontal_line(r.project.cam.follower.roller_radius, "roller radius", kJumpColor);
    }
    // Radii go to ±∞ at inflections: show the working range.
    const double limit = 4 * (r.project.cam.base_radius + r.program.stroke());
    radius.y_range = AxisRange{-limit, limit};
    for (const AngleRange& u : r.analysis->undercut)
      radius.add_band(u.from * kDegreesPerRadian, u.to * kDegreesPerRadian, "undercut", kJumpColor);
  } else {
    f.title = "Pressure angle at the pitch radius";
    std::vector<double> phi;
    for (double a : r.barrel_pressure_angle) phi.push_back(a * kDegreesPerRadian);
    phi.push_back(phi.front());
    pressure.add(series("", x, phi));
    std::vector<double> z;
    for (const Kinematics& k : r.kinematics) z.push_back(r.project.cam.z0 + k.displacement);
    z.push_back(z.front());
    radius.y_label = "track height z [mm]";
    radius.add(series("", x, z));
  }
  mark_segments(r, pressure, true);
  mark_segments(r, radius, false);
  return f;
}

Figure profile_figure(const CamJobResult& r) {
  Figure f(800, 800);
  Plot& plot = f.add_panel();
  plot.equal_aspect = true;
  plot.x_label = "x [mm]";
  plot.y_label = "y [mm]";
  if (r.plate) {
    f.title = "Cam profile: degree " + std::to_string(r.profile.degree()) + ", " +
              std::to_string(r.profile.size()) + " control points, " +
              std::to_string(r.conversion.arcs.size()) + " arcs";
    add_points(plot, "contour (NURBS)", sample_curve(r.profile, 2000), Series::Style::line, "#0072b2");
    add_points(plot, "control polygon", r.profile.control_points(), Series::Style::line_markers, "#cc79a7");
    add_circle(plot, "base circle", r.project.cam.base_radius, Series::Style::dashed);
    if (r.project.cam.follower.kind == FollowerKind::Roller) {
      std::vector<Eigen::Vector2d> pitch;
      for (double theta : r.angles) {
        Eigen::Vector2d p[1];
        r.plate->pitch(theta, 0, p);
        pitch.push_back(p[0]);
      }
      pitch.push_back(pitch.front());
      add_points(plot, "pitch curve", pitch, Series::Style::dashed, "#009e73");
    }
  } else {
    f.title = "Track centre line, developed: degree " + std::to_string(r.track.degree()) + ", " +
              std::to_string(r.track.size()) + " control points";
    plot.equal_aspect = false;
    plot.x_label = "arc length on the pitch cylinder [mm]";
    plot.y_label = "z [mm]";
    std::vector<double> x, z;
    double psi0 = 0.0, previous = 0.0;
    for (int k = 0; k <= 2000; ++k) {
      const Eigen::Vector3d p = r.track(r.track.front() + (r.track.back() - r.track.front()) * k / 2000);
      double psi = std::atan2(p.y(), p.x());
      if (k == 0) psi0 = previous = psi;
      psi = previous + std::remainder(psi - previous, 2 * std::numbers::pi);
      previous = psi;
      x.push_back((psi - psi0) * r.project.cam.cylinder_radius);
      z.push_back(p.z());
    }
    plot.add(series("track centre (NURBS)", std::move(x), std::move(z)));
  }
  return f;
}

std::vector<std::pair<double, double>> radial_error_samples(const CamJobResult& r, int count) {
  const NurbsCurve2d& c = r.conversion.curve;
  std::vector<std::pair<double, double>> out;
  for (int k = 0; k <= count; ++k) {
    const double u = c.front() + (c.back() - c.front()) * k / count;
    double psi;
    const double e = radial_error_at(c, r.profile_function, u, u, &psi);
    out.emplace_back(psi * kDegreesPerRadian, e);
  }
  return out;
}

Figure conversion_error_figure(const CamJobResult& r) {
  Figure f(900, 420);
  f.title = "Measured radial error of the NURBS profile (tolerance " +
            number_text(to_micrometres(r.conversion.tolerance)) + " µm)";
  Plot& plot = f.add_panel();
  plot.x_label = "polar angle ψ [deg]";
  plot.y_label = "radial error [µm]";
  std::vector<double> x, y;
  for (const auto& [psi, e] : radial_error_samples(r, 4000)) x.push_back(psi), y.push_back(e * 1e3);
  plot.add(series("|ρ − R(ψ)|", std::move(x), std::move(y)));
  plot.add_horizontal_line(r.conversion.tolerance * 1e3, "tolerance", kJumpColor);
  for (std::size_t j = 1; j < r.conversion.arcs.size(); ++j)
    plot.add_vertical_line(r.conversion.arcs[j].start * kDegreesPerRadian);
  plot.add_annotation(r.conversion.arcs.front().start * kDegreesPerRadian,
                      r.conversion.tolerance * 1e3, "grey lines: arc junctions");
  return f;
}

}  // namespace polarform
