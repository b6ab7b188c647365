#include "jobs/viz/viz_plots.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <set>

#include "export/plot_style.h"
#include "src/number_text.h"
#include "src/nurbs/tessellation.h"
#include "src/units.h"

namespace polarform {

namespace {

// The grid coordinates of a surface point: (φ or z, θ), θ in [0, 2π).
struct Coordinates {
  double a, theta;
};

Coordinates coordinates(const VizJobResult& r, double u, double v) {
  const Eigen::Vector3d p = r.field.surface.point(u, v);
  double theta = std::atan2(p.y(), p.x());
  if (theta < 0) theta += 2 * std::numbers::pi;
  const double a = r.grid.setup == GridSetup::spherical
                       ? std::acos(std::clamp(p.z() / p.norm(), -1.0, 1.0))
                       : p.z();
  return {a, theta};
}

// Up to four distinct values of x spread over its range (the grid's rows or columns).
std::vector<double> levels(const Eigen::VectorXd& x) {
  std::set<double> distinct(x.data(), x.data() + x.size());
  const std::vector<double> all(distinct.begin(), distinct.end());
  std::vector<double> out;
  const std::size_t n = all.size(), want = std::min<std::size_t>(4, n);
  for (std::size_t i = 0; i < want; ++i)
    out.push_back(all[want == 1 ? 0 : i * (n - 1) / (want - 1)]);
  return out;
}

// The parameter t in [t0, t1] at which the monotone g(t) reaches `target` (bisection).
double solve(const std::function<double(double)>& g, double t0, double t1, double target) {
  const bool increasing = g(t1) >= g(t0);
  for (int it = 0; it < 60; ++it) {
    const double m = 0.5 * (t0 + t1);
    ((g(m) < target) == increasing ? t0 : t1) = m;
  }
  return 0.5 * (t0 + t1);
}

// Appends (θ, y), θ in [0°, 360°), to a curve along the azimuth; where the curve wraps through the
// 360° seam it ends at one edge of the panel and goes on from the other (a NaN breaks the line),
// instead of a line back across the panel.
void add_azimuth_point(Series& s, double theta_deg, double y) {
  if (!s.x.empty() && std::abs(theta_deg - s.x.back()) > 180) {
    const double x0 = s.x.back(), y0 = s.y.back();
    const bool forward = theta_deg < x0;  // 359° -> 1°: through 360° onwards
    const double unwrapped = forward ? theta_deg + 360 : theta_deg - 360;
    const double edge = forward ? 360 : 0;
    const double y_edge = y0 + (y - y0) * (edge - x0) / (unwrapped - x0);
    s.x.insert(s.x.end(), {edge, std::numeric_limits<double>::quiet_NaN(), 360 - edge});
    s.y.insert(s.y.end(), {y_edge, std::numeric_limits<double>::quiet_NaN(), y_edge});
  }
  s.x.push_back(theta_deg);
  s.y.push_back(y);
}

double value(const VizJobResult& r, double u, double v) {
  double p = 0.0;
  r.field.F.point(u, v, &p);
  return p;
}

}  // namespace

Figure viz_preview_figure(const VizJobResult& r) {
  const NurbsSurface& S = r.field.surface;
  const bool sph = r.grid.setup == GridSetup::spherical;
  const Eigen::VectorXd& a = sph ? r.grid.phi : r.grid.z;
  const double a_unit = sph ? kDegreesPerRadian : 1.0;
  const std::string a_name = sph ? "polar angle φ [deg]" : "height z [mm]";
  Figure fig(800, 900);
  fig.title = "Field '" + r.grid.value_name + "' on a " + (sph ? "spherical" : "cylindrical") +
              " set-up (Bae 2002, §5.3)";
  const double v_mid = 0.5 * (S.front_v() + S.back_v()), u_mid = 0.5 * (S.front_u() + S.back_u());

  Plot& rows = fig.add_panel();
  rows.title = "Along θ: data (markers) and the fitted F at four " +
               std::string(sph ? "polar angles" : "heights");
  rows.x_label = "azimuth θ [deg]";
  rows.y_label = r.grid.value_name;
  std::size_t colour = 0;
  for (double level : levels(a)) {
    const std::string c(plot_style::palette[colour++ % plot_style::palette.size()]);
    const double u =
        solve([&](double t) { return coordinates(r, t, v_mid).a; }, S.front_u(), S.back_u(), level);
    Series fit{(sph ? "φ = " : "z = ") + format_trimmed(level * a_unit, 3),
               {},
               {},
               Series::Style::line,
               c};
    // The azimuth of S(u, v) depends on v alone (S = F·B); taken at the middle row, it is
    // defined at the poles too.
    for (double v : tessellation_parameters(S.knots_v(), S.front_v(), S.back_v(), 400))
      add_azimuth_point(fit, coordinates(r, u_mid, v).theta * kDegreesPerRadian, value(r, u, v));
    Series data{"", {}, {}, Series::Style::markers, c};
    for (Eigen::Index k = 0; k < a.size(); ++k)
      if (a[k] == level) {
        double t = std::fmod(r.grid.theta[k], 2 * std::numbers::pi);
        data.x.push_back((t < 0 ? t + 2 * std::numbers::pi : t) * kDegreesPerRadian);
        data.y.push_back(r.grid.value[k]);
      }
    rows.add(std::move(fit));
    rows.add(std::move(data));
  }
  rows.x_range = AxisRange{0, 360};
  rows.x_tick_step = 45;

  Plot& cols = fig.add_panel();
  cols.title = "Along " + std::string(sph ? "φ" : "z") +
               ": data (markers) and the fitted F at four azimuths";
  cols.x_label = a_name;
  cols.y_label = r.grid.value_name;
  colour = 0;
  for (double level : levels(r.grid.theta)) {
    const std::string c(plot_style::palette[colour++ % plot_style::palette.size()]);
    double target = std::fmod(level, 2 * std::numbers::pi);
    if (target < 0) target += 2 * std::numbers::pi;
    // θ(v) increases from the start of the azimuth range; unwrap it past 2π.
    const double theta0 = coordinates(r, u_mid, S.front_v()).theta;
    const auto unwrapped = [&](double t) {
      const double th = coordinates(r, u_mid, t).theta;
      return th < theta0 - 1e-9 ? th + 2 * std::numbers::pi : th;
    };
    const double v = solve(unwrapped, S.front_v(), S.back_v(),
                           target < theta0 - 1e-9 ? target + 2 * std::numbers::pi : target);
    Series fit{"θ = " + format_trimmed(target * kDegreesPerRadian, 3) + "°",
               {},
               {},
               Series::Style::line,
               c};
    for (double u : tessellation_parameters(S.knots_u(), S.front_u(), S.back_u(), 400)) {
      fit.x.push_back(coordinates(r, u, v).a * a_unit);
      fit.y.push_back(value(r, u, v));
    }
    Series data{"", {}, {}, Series::Style::markers, c};
    for (Eigen::Index k = 0; k < a.size(); ++k)
      if (r.grid.theta[k] == level) {
        data.x.push_back(a[k] * a_unit);
        data.y.push_back(r.grid.value[k]);
      }
    cols.add(std::move(fit));
    cols.add(std::move(data));
  }
  return fig;
}

}  // namespace polarform
