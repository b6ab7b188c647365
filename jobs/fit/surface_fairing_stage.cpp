#include "jobs/fit/surface_fairing_stage.h"

#include <string>
#include <utility>
#include <variant>

#include "src/number_text.h"

namespace polarform {

SurfaceFitFairing fair_surface_fit(RotationalFit& fit, const Eigen::Matrix3Xd& points,
                                   const ProfileFairingOptions& options) {
  if (auto* c = std::get_if<CylindricalFit>(&fit.fit))
    return fair_cylindrical_fit(*c, points, options);
  return fair_spherical_fit(std::get<SphericalFit>(fit.fit), points, options);
}

nlohmann::ordered_json surface_fairing_json(const SurfaceFitFairing& f) {
  nlohmann::ordered_json knots = nlohmann::ordered_json::array();
  for (const auto& [direction, d] : {std::pair{"u", &f.u}, std::pair{"v", &f.v}})
    for (const FairingStep& s : d->steps)
      knots.push_back({{"direction", direction},
                       {"u", s.u},
                       {"jump_before", s.jump_before},
                       {"jump_after", s.jump_after},
                       {"bound_mm", s.bound}});
  return {{"method", fairing_method_name(f.method)},
          {"tolerance_mm", f.tolerance},
          {"passes", f.u.steps.size() + f.v.steps.size()},
          {"knots_faired", knots},
          {"max_jump_before_u", f.u.max_jump_before},
          {"max_jump_after_u", f.u.max_jump_after},
          {"max_jump_before_v", f.v.max_jump_before},
          {"max_jump_after_v", f.v.max_jump_after},
          {"bound_mm", f.u.bound + f.v.bound},
          {"measured_deviation_mm", f.measured_deviation},
          {"error_before_max_mm", f.error_before}};
}

Figure surface_fairing_figure(const SurfaceFitFairing& f) {
  Figure fig(800, 600);
  fig.title = "Fairing of F's net (" + fairing_method_name(f.method) + "): surface moved " +
              number_text(f.measured_deviation) + " mm of a bound " +
              number_text(f.u.bound + f.v.bound) + " mm";
  for (const auto& [direction, d] : {std::pair{"u", &f.u}, std::pair{"v", &f.v}}) {
    Plot& p = fig.add_panel();
    p.x_label = std::string("knot of ") + direction;
    p.y_label = "jump of F's p-th derivative";
    Series before{"before", {}, {}, Series::Style::markers, "#aaaaaa"};
    Series after{"after", {}, {}, Series::Style::markers, ""};
    for (const FairingStep& s : d->steps) {
      before.x.push_back(s.u);
      before.y.push_back(s.jump_before);
      after.x.push_back(s.u);
      after.y.push_back(s.jump_after);
    }
    p.add(std::move(before));
    p.add(std::move(after));
  }
  return fig;
}

}  // namespace polarform
