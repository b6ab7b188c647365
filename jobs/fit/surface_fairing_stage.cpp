#include "jobs/fit/surface_fairing_stage.h"

#include <variant>

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

}  // namespace polarform
