#include "jobs/fit/fit_plots.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "src/nurbs/tessellation.h"
#include "src/units.h"

namespace polarform {

namespace {

constexpr int kMarkers = 4000;

std::string mm(double x) {
  std::ostringstream o;
  o.precision(3);
  o << x << " mm";
  return o.str();
}

std::string shown(Eigen::Index n, int stride) {
  return stride == 1 ? "all " + std::to_string(n) + " points"
                     : "every " + std::to_string(stride) + "th of " + std::to_string(n) + " points";
}

// Signed deviation d against x for every stride-th point, with ±rms reference lines.
void deviation_panel(Plot& p, const std::vector<double>& x, const Eigen::VectorXd& d, int stride,
                     double rms) {
  Series s;
  s.style = Series::Style::markers;
  for (std::size_t k = 0; k < x.size(); k += static_cast<std::size_t>(stride)) {
    s.x.push_back(x[k]);
    s.y.push_back(d[static_cast<Eigen::Index>(k)]);
  }
  p.add(std::move(s));
  p.add_horizontal_line(rms, "+rms");
  p.add_horizontal_line(-rms, "−rms");
  p.y_label = "signed deviation [mm]";
}

void histogram_panel(Plot& p, const Eigen::VectorXd& d, double limit) {
  const int bins = 60;
  std::vector<double> count(bins, 0.0);
  for (Eigen::Index k = 0; k < d.size(); ++k) {
    const int b = static_cast<int>(std::floor((d[k] + limit) / (2 * limit) * bins));
    if (b >= 0 && b < bins) count[static_cast<std::size_t>(b)] += 1;
  }
  Series s;
  s.label = "points per bin";
  for (int b = 0; b < bins; ++b) {
    const double x0 = -limit + 2 * limit * b / bins, x1 = -limit + 2 * limit * (b + 1) / bins;
    s.x.insert(s.x.end(), {x0, x1});
    s.y.insert(s.y.end(), {count[static_cast<std::size_t>(b)], count[static_cast<std::size_t>(b)]});
  }
  p.add(std::move(s));
  p.title = "Histogram of the signed deviation (within ±p99.9 of |d|)";
  p.x_label = "signed deviation [mm]";
  p.y_label = "points";
}

Figure polar_preview(const FitJobResult& r) {
  const PolarCurveFit& f = std::get<ProfileFit>(r.fit).polar;
  const FitReport& rep = f.report;
  Figure fig(800, 1000);
  fig.title = "Polar curve fit of " + r.input.filename().string() + ": rms " + mm(rep.error.rms);
  const Eigen::Matrix2Xd local = r.plane.frame.to_local(r.points).topRows(2);
  const int stride = marker_stride(local.cols(), kMarkers);
  Plot& shape = fig.add_panel();
  shape.title =
      "Data (" + shown(local.cols(), stride) + ") and the fitted curve, profile-plane coordinates";
  shape.equal_aspect = true;
  shape.x_label = "x [mm]";
  shape.y_label = "y [mm]";
  Series data{"data", {}, {}, Series::Style::markers, "#999999"};
  for (Eigen::Index k = 0; k < local.cols(); k += stride) {
    data.x.push_back(local(0, k));
    data.y.push_back(local(1, k));
  }
  shape.add(std::move(data));
  Series curve{"fitted NURBS curve", {}, {}, Series::Style::line, ""};
  for (const Eigen::Vector2d& p : tessellate(f.curve, 2000).points) {
    curve.x.push_back(p.x());
    curve.y.push_back(p.y());
  }
  shape.add(std::move(curve));
  Plot& dev = fig.add_panel();
  dev.title = "Signed deviation (closest-point distance, + outside) against polar angle";
  dev.x_label = "polar angle θ about the centre [deg]";
  std::vector<double> angle(static_cast<std::size_t>(local.cols()));
  for (Eigen::Index k = 0; k < local.cols(); ++k)
    angle[static_cast<std::size_t>(k)] =
        degrees_in_turn(std::atan2(local(1, k) - f.centre.y(), local(0, k) - f.centre.x()));
  deviation_panel(dev, angle, rep.signed_distance, stride, rep.error.rms);
  dev.x_range = AxisRange{0, 360};
  dev.x_tick_step = 45;
  return fig;
}

Figure surface_preview(const FitJobResult& r) {
  const RotationalFit& f = std::get<RotationalFit>(r.fit);
  const FitReport& rep = f.report();
  Figure fig(800, 1100);
  fig.title = (f.method() == FitMethod::spherical ? "Spherical" : "Cylindrical") +
              std::string(" fit of ") + r.input.filename().string() + ": rms " + mm(rep.error.rms);
  const Eigen::Matrix3Xd local = f.frame().frame.to_local(r.points);
  const Eigen::VectorXd& d = rep.signed_distance;
  const double limit = std::max(abs_quantile(d, 0.999), 1e-12);
  histogram_panel(fig.add_panel(), d, limit);
  const int stride = marker_stride(local.cols(), kMarkers);
  std::vector<double> theta(static_cast<std::size_t>(local.cols())), second(theta.size());
  for (Eigen::Index k = 0; k < local.cols(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    theta[i] = degrees_in_turn(std::atan2(local(1, k), local(0, k)));
    second[i] = f.method() == FitMethod::spherical
                    ? std::acos(std::clamp(local(2, k) / local.col(k).norm(), -1.0, 1.0)) *
                          kDegreesPerRadian
                    : local(2, k);
  }
  Plot& by_theta = fig.add_panel();
  by_theta.title = "Signed deviation against azimuth θ (" + shown(local.cols(), stride) + ")";
  by_theta.x_label = "azimuth θ in the fit's frame [deg]";
  deviation_panel(by_theta, theta, d, stride, rep.error.rms);
  by_theta.x_range = AxisRange{0, 360};
  by_theta.x_tick_step = 45;
  Plot& by_second = fig.add_panel();
  by_second.title = f.method() == FitMethod::spherical ? "Signed deviation against polar angle φ"
                                                       : "Signed deviation against height z";
  by_second.x_label = f.method() == FitMethod::spherical
                          ? "polar angle φ from the frame's k axis [deg]"
                          : "height z along the frame's k axis [mm]";
  deviation_panel(by_second, second, d, stride, rep.error.rms);
  return fig;
}

}  // namespace

int marker_stride(Eigen::Index n, int limit) {
  return std::max(1, static_cast<int>((n + limit - 1) / limit));
}

Figure fit_preview_figure(const FitJobResult& r) {
  return r.profile() ? polar_preview(r) : surface_preview(r);
}

}  // namespace polarform
