#include "jobs/fit/profile_curvature_figure.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "src/number_text.h"

namespace polarform {

namespace {

// κ against the angle, sorted by angle (the curve may wrap through 360°).
Series curvature_series(const ProfileInterrogation& q, std::string label, std::string color) {
  std::vector<std::pair<double, double>> samples;
  for (std::size_t i = 0; i < q.angle_deg.size(); ++i)
    samples.emplace_back(q.angle_deg[i], q.curvature[i]);
  std::sort(samples.begin(), samples.end());
  Series curve{std::move(label), {}, {}, Series::Style::line, std::move(color)};
  for (const auto& [a, k] : samples) {
    curve.x.push_back(a);
    curve.y.push_back(k);
  }
  return curve;
}

Series jump_series(const ProfileInterrogation& q, std::string label, std::string color) {
  Series bars{std::move(label), {}, {}, Series::Style::markers, std::move(color)};
  for (const ProfileInterrogation::Place& p : q.derivative_jumps) {
    bars.x.push_back(p.angle_deg);
    bars.y.push_back(p.value);
  }
  return bars;
}

}  // namespace

Figure profile_curvature_figure(const ProfileInterrogation& q, const std::string& angle_label,
                                const ProfileInterrogation* before) {
  Figure f(900, 620);
  f.shared_x = true;
  f.title =
      std::string(before ? "Curvature of the faired curve: " : "Curvature of the fitted curve: ") +
      std::to_string(q.inflections.size()) +
      (q.inflections.size() == 1 ? " inflection" : " inflections");
  if (before) f.title += " (" + std::to_string(before->inflections.size()) + " before fairing)";
  Plot& kappa = f.add_panel();
  kappa.x_label = angle_label;
  kappa.y_label = "signed curvature κ [1/mm]";
  kappa.x_range = AxisRange{0, 360};
  kappa.x_tick_step = 30;
  if (before) kappa.add(curvature_series(*before, "κ(θ) before fairing", "#aaa"));
  kappa.add(curvature_series(q, before ? "κ(θ) faired" : "κ(θ) of the NURBS curve", {}));
  kappa.add_horizontal_line(0.0);
  for (const ProfileInterrogation::Place& p : q.inflections)
    kappa.add_highlight(p.angle_deg, 0.0,
                        "inflection at θ = " + format_trimmed(p.angle_deg, 4) + "°");
  Plot& jumps = f.add_panel();
  jumps.y_label = "jump of C^(" + std::to_string(q.order) + ") at knots";
  if (before) jumps.add(jump_series(*before, "before fairing", "#aaa"));
  jumps.add(jump_series(q, before ? "faired" : "", {}));
  return f;
}

}  // namespace polarform
