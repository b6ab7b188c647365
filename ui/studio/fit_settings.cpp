#include "ui/studio/fit_settings.h"

#include <utility>

namespace polarform::studio {

FitSettings fit_settings(const FitProject& p) {
  FitSettings s;
  s.method = static_cast<int>(p.method);
  s.closure = static_cast<int>(p.closure);
  if (p.pole) s.pole = static_cast<int>(*p.pole);
  if (p.degree) s.degree_u = p.degree->first, s.degree_v = p.degree->second;
  if (p.ctrl) s.size_u = p.ctrl->first, s.size_v = p.ctrl->second;
  s.automatic_net = !p.ctrl;
  s.use_tolerance = p.tolerance.has_value();
  if (p.tolerance) s.tolerance = *p.tolerance;
  s.measure = static_cast<int>(p.measure);
  s.center = p.center;
  s.axis = p.axis;
  s.skip_bad = p.skip_bad;
  s.reject_outliers = p.reject_outliers;
  s.fairness = static_cast<int>(p.fairness);
  s.fairness_weight = p.fairness_weight;
  s.quartic_base = p.base == ArcKind::quartic;
  s.revolution = static_cast<int>(p.revolution);
  return s;
}

FitProject fit_project(const FitSettings& s, const std::filesystem::path& scan) {
  FitProject p;
  p.scan = scan;
  p.method = static_cast<FitJobMethod>(s.method);
  p.closure = static_cast<Closure>(s.closure);
  if (static_cast<PoleTreatment>(s.pole) != PoleTreatment::automatic)
    p.pole = static_cast<PoleTreatment>(s.pole);
  p.degree = std::make_pair(s.degree_u, s.degree_v);
  if (s.use_tolerance)
    p.tolerance = s.tolerance;
  else if (!s.automatic_net)
    p.ctrl = std::make_pair(s.size_u, s.size_v);
  p.measure = static_cast<ToleranceMeasure>(s.measure);
  p.center = s.center;
  p.axis = s.axis;
  p.skip_bad = s.skip_bad;
  p.reject_outliers = s.reject_outliers;
  p.fairness = static_cast<FairnessOptions::Mode>(s.fairness);
  p.fairness_weight = s.fairness_weight;
  p.base = s.quartic_base ? ArcKind::quartic : ArcKind::rqb;
  p.revolution = static_cast<RevolutionMode>(s.revolution);
  return p;
}

}  // namespace polarform::studio
