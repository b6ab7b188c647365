#include "jobs/scan_cam/scan_cam_plots.h"

#include <cmath>
#include <numbers>

#include "designers/cam/contour_polar_function.h"
#include "jobs/fit/fit_plots.h"
#include "jobs/scan_cam/scan_cam_design_report.h"
#include "src/number_text.h"
#include "src/nurbs/tessellation.h"
#include "src/units.h"

namespace polarform {

namespace {

const char* kNames[4] = {"s [mm]", "v = ds/dθ [mm/rad]", "a = d²s/dθ² [mm/rad²]",
                         "j = d³s/dθ³ [mm/rad³]"};

std::vector<double> degrees(const std::vector<double>& radians) {
  std::vector<double> d;
  for (double r : radians) d.push_back(r * kDegreesPerRadian);
  return d;
}

std::vector<double> grid(int count) {
  std::vector<double> t;
  for (int i = 0; i <= count; ++i) t.push_back(2 * std::numbers::pi * i / count);
  return t;
}

void cam_angle_axis(Plot& p) {
  p.x_label = "cam angle θ [deg]";
  p.x_range = AxisRange{0, 360};
  p.x_tick_step = 45;
}

// The recovered rises and returns shaded over their fitted boundaries (scan angles, split where
// they pass 360°); on the displacement panel (rest height y0) each is named by its law.
void shade_motions(Plot& p, const RecoveredDesign& d, const double* rest_height) {
  constexpr double kFull = 360.0;
  bool legend[2] = {false, false};  // rise, return
  for (const IdentifiedMotion& m : d.motions) {
    const LawFit& f = m.law();
    const double from = std::fmod(std::fmod(f.start * kDegreesPerRadian, kFull) + kFull, kFull);
    const double to = from + (f.end - f.start) * kDegreesPerRadian;
    const bool rise = m.kind == SegmentKind::Rise;
    bool& shown = legend[rise ? 0 : 1];
    const char* color = rise ? "#56B4E9" : "#E69F00";
    p.add_band(from, std::min(to, kFull),
               shown  ? ""
               : rise ? "rise (recovered)"
                      : "return (recovered)",
               color);
    shown = true;
    if (to > kFull) p.add_band(0.0, to - kFull, "", color);
    if (rest_height)
      p.add_annotation(std::fmod(0.5 * (from + to), kFull), f.level + 0.5 * f.lift - *rest_height,
                       law_label(f.shape));
  }
}

}  // namespace

std::array<std::vector<double>, 4> recovered_svaj(const ScannedCam& scan,
                                                  const std::vector<double>& theta) {
  std::array<std::vector<double>, 4> out;
  for (double t : theta) {
    double d[4];
    scan.displacement_derivatives(t, 3, d);
    for (std::size_t k = 0; k < 4; ++k) out[k].push_back(d[k]);
  }
  return out;
}

Figure scan_svaj_figure(const ScanCamJobResult& r) {
  const ScannedCam& s = r.scan;
  Figure fig(800, 1000);
  fig.title = "Recovered follower motion (degree-" +
              std::to_string(s.displacement.height.degree()) + " B-spline, smoothing by GCV)";
  fig.shared_x = true;
  const std::vector<double> theta = grid(1440);
  const auto svaj = recovered_svaj(s, theta);
  for (std::size_t k = 0; k < 4; ++k) {
    Plot& p = fig.add_panel();
    p.y_label = kNames[k];
    cam_angle_axis(p);
    if (k == 0) {
      Series data{"scan samples", {}, {}, Series::Style::markers, "#aaaaaa"};
      const int stride = marker_stride(s.samples.theta.size(), 1500);
      for (Eigen::Index i = 0; i < s.samples.theta.size(); i += stride) {
        data.x.push_back(s.samples.theta[i] * kDegreesPerRadian);
        data.y.push_back(s.samples.height[i] - s.rest_height);
      }
      p.add(std::move(data));
    }
    p.add(Series{"recovered", degrees(theta), svaj[k], Series::Style::line, ""});
    if (r.design) shade_motions(p, *r.design, k == 0 ? &s.rest_height : nullptr);
    if (static_cast<int>(k) > r.resolution.resolved_order) {
      const DerivativeResolution& d = r.resolution.derivatives[k];
      p.title = "unresolved: noise " + number_text(d.noise) + " against a peak of " +
                number_text(d.signal) + " (needs ≥ 1/" + number_text(kResolvedRatio) + ")";
    }
    if (r.nominal) {
      Series nominal{"nominal", degrees(theta), {}, Series::Style::dashed, ""};
      for (double t : theta) {
        double d[4];
        r.nominal->program().derivatives(t, 3, d);
        nominal.y.push_back(d[k]);
      }
      p.add(std::move(nominal));
    }
  }
  return fig;
}

Figure scan_fairing_figure(const ScanCamJobResult& r) {
  const ScanCamFairing& f = *r.fairing;
  Figure fig(800, 700);
  const std::string refit = f.fairing.refit
                                ? "refitted along the recovered design (" +
                                      std::to_string(f.fairing.refit->breaks) + " boundaries, " +
                                      std::to_string(f.fairing.refit->dwells) + " dwells), "
                                : std::string();
  fig.title = "Fairing of s(θ) (" + fairing_method_name(f.fairing.method) + ", " + refit +
              std::to_string(f.fairing.steps.size()) + " knots, moved " +
              number_text(f.fairing.measured_deviation) + " mm)";
  const std::vector<double> theta = grid(1440);
  Plot& a = fig.add_panel();
  a.y_label = kNames[2];
  cam_angle_axis(a);
  Series before{"before fairing", degrees(theta), {}, Series::Style::line, "#aaaaaa"};
  Series after{"faired", degrees(theta), {}, Series::Style::line, ""};
  for (double t : theta) {
    before.y.push_back(f.before.spline().derivatives(t, 2)(0, 2));
    after.y.push_back(r.scan.displacement.height.spline().derivatives(t, 2)(0, 2));
  }
  a.add(std::move(before));
  a.add(std::move(after));
  if (r.nominal) {
    Series nominal{"nominal", degrees(theta), {}, Series::Style::dashed, ""};
    for (double t : theta) {
      double d[3];
      r.nominal->program().derivatives(t, 2, d);
      nominal.y.push_back(d[2]);
    }
    a.add(std::move(nominal));
  }
  Plot& jumps = fig.add_panel();
  jumps.y_label = "jump of s's p-th derivative at the knots faired";
  cam_angle_axis(jumps);
  Series jb{"before", {}, {}, Series::Style::markers, "#aaaaaa"},
      ja{"after", {}, {}, Series::Style::markers, ""};
  for (const FairingStep& k : f.fairing.steps) {
    jb.x.push_back(k.u * kDegreesPerRadian);
    jb.y.push_back(k.jump_before);
    ja.x.push_back(k.u * kDegreesPerRadian);
    ja.y.push_back(k.jump_after);
  }
  jumps.add(std::move(jb));
  jumps.add(std::move(ja));
  return fig;
}

Figure scan_svaj_difference_figure(const ScanCamJobResult& r) {
  const NominalComparison& c = *r.comparison;
  Figure fig(800, 1000);
  fig.title = "Recovered minus nominal motion";
  fig.shared_x = true;
  for (std::size_t k = 0; k < 4; ++k) {
    Plot& p = fig.add_panel();
    p.y_label = "Δ" + std::string(kNames[k]);
    cam_angle_axis(p);
    p.add(Series{"", degrees(c.theta), c.svaj_difference[k], Series::Style::line, ""});
  }
  return fig;
}

Figure scan_deviation_figure(const ScanCamJobResult& r) {
  const ScannedCam& s = r.scan;
  Figure fig(800, 500);
  Plot& p = fig.add_panel();
  cam_angle_axis(p);
  p.y_label = "deviation [mm]";
  const int stride = marker_stride(s.samples.theta.size(), 3000);
  if (r.comparison) {
    const NominalComparison& c = *r.comparison;
    p.title = "Deviation from the nominal profile (+ = more material), after phase alignment";
    Series points{"scanned points (radial)", {}, {}, Series::Style::markers, "#bbbbbb"};
    for (Eigen::Index i = 0; i < s.samples.theta.size(); i += stride) {
      points.x.push_back(s.samples.theta[i] * kDegreesPerRadian);
      points.y.push_back(c.point_radial[i]);
    }
    p.add(std::move(points));
    p.add(Series{"fitted profile, normal", degrees(c.theta), c.normal, Series::Style::line, ""});
    p.add(Series{"fitted profile, radial", degrees(c.theta), c.radial, Series::Style::dashed, ""});
  } else {
    p.title = "Scanned points about the fitted profile (closest-point distance, + outside)";
    Series points{"scanned points", {}, {}, Series::Style::markers, "#888888"};
    for (Eigen::Index i = 0; i < s.samples.theta.size(); i += stride) {
      points.x.push_back(s.samples.theta[i] * kDegreesPerRadian);
      points.y.push_back(s.fit.report.signed_distance[i]);
    }
    p.add(std::move(points));
  }
  p.add_horizontal_line(3 * s.contour_noise, "+3σ̂", "#009E73");
  p.add_horizontal_line(-3 * s.contour_noise, "−3σ̂", "#009E73");
  if (r.tolerance) {
    p.add_horizontal_line(*r.tolerance, "+tol", "#D55E00");
    p.add_horizontal_line(-*r.tolerance, "−tol", "#D55E00");
  }
  return fig;
}

Figure scan_profile_figure(const ScanCamJobResult& r) {
  const ScannedCam& s = r.scan;
  Figure fig(800, 800);
  Plot& p = fig.add_panel();
  p.title = "Profile in the cam frame (follower on +y at θ = 0)";
  p.equal_aspect = true;
  p.x_label = "x [mm]";
  p.y_label = "y [mm]";
  Series data{"scanned points", {}, {}, Series::Style::markers, "#aaaaaa"};
  const int stride = marker_stride(s.contour.cols(), 3000);
  for (Eigen::Index i = 0; i < s.contour.cols(); i += stride) {
    data.x.push_back(s.contour(0, i));
    data.y.push_back(s.contour(1, i));
  }
  p.add(std::move(data));
  Series fit{"fitted NURBS profile", {}, {}, Series::Style::line, ""};
  for (const Eigen::Vector2d& q : tessellate(s.fit.curve, 2000).points) {
    fit.x.push_back(q.x());
    fit.y.push_back(q.y());
  }
  p.add(std::move(fit));
  if (r.nominal) {
    Series nominal{"nominal contour", {}, {}, Series::Style::dashed, ""};
    for (int i = 0; i <= 1440; ++i) {
      Eigen::Vector2d q;
      r.nominal->contour(2 * std::numbers::pi * i / 1440, 0, &q);
      nominal.x.push_back(q.x());
      nominal.y.push_back(q.y());
    }
    p.add(std::move(nominal));
  }
  if (s.profile.bore_circle) {
    Series bore{"bore (circle fit)", {}, {}, Series::Style::line, "#666666"};
    const CircleFit& b = *s.profile.bore_circle;
    // Into the cam frame as the contour went: mirrored first, then turned back by the phase.
    const double phase = s.alignment ? s.alignment->phase : 0.0;
    const Eigen::Vector2d m(b.centre.x(), s.mirrored ? -b.centre.y() : b.centre.y());
    const Eigen::Vector2d centre(std::cos(phase) * m.x() + std::sin(phase) * m.y(),
                                 -std::sin(phase) * m.x() + std::cos(phase) * m.y());
    for (int i = 0; i <= 360; ++i) {
      const double a = 2 * std::numbers::pi * i / 360;
      bore.x.push_back(centre.x() + b.radius * std::cos(a));
      bore.y.push_back(centre.y() + b.radius * std::sin(a));
    }
    p.add(std::move(bore));
  }
  return fig;
}

}  // namespace polarform
