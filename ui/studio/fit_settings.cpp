#include "ui/studio/fit_settings.h"

#include <utility>

namespace polarform::studio {

RotationalFitOptions to_fit_options(const FitSettings& s, int threads) {
  FunctionFitOptions f;
  f.degree_u = s.degree_u;
  f.degree_v = s.degree_v;
  if (s.use_tolerance) {
    f.tolerance = s.tolerance;
    f.measure = static_cast<ToleranceMeasure>(s.measure);
  } else {
    f.size_u = s.size_u;
    f.size_v = s.size_v;
  }
  f.fairness.mode = static_cast<FairnessOptions::Mode>(s.fairness);
  f.fairness.weight = s.fairness_weight;
  f.threads = threads;
  RotationalFitOptions o;
  o.spherical.function = f;
  o.cylindrical.function = f;
  o.spherical.frame.quadric.threads = threads;
  o.cylindrical.frame.quadric.threads = threads;
  const ArcKind base = s.quartic_base ? ArcKind::quartic : ArcKind::rqb;
  o.spherical.base_kind = o.cylindrical.base_kind = base;
  o.spherical.closure = o.cylindrical.closure = static_cast<Closure>(s.closure);
  o.spherical.north = o.spherical.south = static_cast<PoleTreatment>(s.pole);
  o.spherical.frame.origin = o.cylindrical.frame.origin = s.center;
  o.spherical.frame.axis = o.cylindrical.frame.axis = s.axis;
  if (s.method == 1) o.method = FitMethod::spherical;
  if (s.method == 2) o.method = FitMethod::cylindrical;
  return o;
}

FitSettings fit_settings(const FitProject& p, std::vector<std::string>& ignored) {
  FitSettings s;
  s.method = p.method == FitJobMethod::spherical     ? 1
             : p.method == FitJobMethod::cylindrical ? 2
                                                     : 0;
  if (p.method == FitJobMethod::polar)
    ignored.push_back("method 'polar' (the studio fits surfaces; use polarform fit for profiles)");
  s.closure = static_cast<int>(p.closure);
  if (p.pole) s.pole = static_cast<int>(*p.pole);
  if (p.degree) s.degree_u = p.degree->first, s.degree_v = p.degree->second;
  if (p.ctrl) s.size_u = p.ctrl->first, s.size_v = p.ctrl->second;
  s.use_tolerance = p.tolerance.has_value();
  if (p.tolerance) s.tolerance = *p.tolerance;
  s.measure = static_cast<int>(p.measure);
  s.center = p.center;
  s.axis = p.axis;
  s.skip_bad = p.skip_bad;
  s.fairness = static_cast<int>(p.fairness);
  s.fairness_weight = p.fairness_weight;
  s.quartic_base = p.base == ArcKind::quartic;
  return s;
}

FitProject fit_project(const FitSettings& s, const std::filesystem::path& scan) {
  FitProject p;
  p.scan = scan;
  p.method = s.method == 1   ? FitJobMethod::spherical
             : s.method == 2 ? FitJobMethod::cylindrical
                             : FitJobMethod::automatic;
  p.closure = static_cast<Closure>(s.closure);
  if (static_cast<PoleTreatment>(s.pole) != PoleTreatment::automatic)
    p.pole = static_cast<PoleTreatment>(s.pole);
  p.degree = std::make_pair(s.degree_u, s.degree_v);
  if (s.use_tolerance)
    p.tolerance = s.tolerance;
  else
    p.ctrl = std::make_pair(s.size_u, s.size_v);
  p.measure = static_cast<ToleranceMeasure>(s.measure);
  p.center = s.center;
  p.axis = s.axis;
  p.skip_bad = s.skip_bad;
  p.fairness = static_cast<FairnessOptions::Mode>(s.fairness);
  p.fairness_weight = s.fairness_weight;
  p.base = s.quartic_base ? ArcKind::quartic : ArcKind::rqb;
  return p;
}

}  // namespace polarform::studio
