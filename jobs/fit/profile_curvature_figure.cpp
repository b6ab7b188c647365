#include "jobs/fit/profile_curvature_figure.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "src/number_text.h"

namespace polarform {

Figure profile_curvature_figure(const ProfileInterrogation& q, const std::string& angle_label) {
  Figure f(900, 620);
  f.shared_x = true;
  f.title = "Curvature of the fitted curve: " + std::to_string(q.inflections.size()) +
            (q.inflections.size() == 1 ? " inflection" : " inflections");
  Plot& kappa = f.add_panel();
  kappa.x_label = angle_label;
  kappa.y_label = "signed curvature κ [1/mm]";
  kappa.x_range = AxisRange{0, 360};
  kappa.x_tick_step = 30;
  // Sorted by angle, broken where the curve wraps through 360°.
  std::vector<std::pair<double, double>> samples;
  for (std::size_t i = 0; i < q.angle_deg.size(); ++i)
    samples.emplace_back(q.angle_deg[i], q.curvature[i]);
  std::sort(samples.begin(), samples.end());
  Series curve{"κ(θ) of the NURBS curve", {}, {}, Series::Style::line, {}};
  for (const auto& [a, k] : samples) {
    curve.x.push_back(a);
    curve.y.push_back(k);
  }
  kappa.add(std::move(curve));
  kappa.add_horizontal_line(0.0);
  for (const ProfileInterrogation::Place& p : q.inflections)
    kappa.add_highlight(p.angle_deg, 0.0,
                        "inflection at θ = " + format_trimmed(p.angle_deg, 4) + "°");
  Plot& jumps = f.add_panel();
  jumps.y_label = "jump of C^(" + std::to_string(q.order) + ") at knots";
  Series bars{"", {}, {}, Series::Style::markers, {}};
  for (const ProfileInterrogation::Place& p : q.derivative_jumps) {
    bars.x.push_back(p.angle_deg);
    bars.y.push_back(p.value);
  }
  jumps.add(std::move(bars));
  return f;
}

}  // namespace polarform
