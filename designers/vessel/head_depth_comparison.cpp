#include "designers/vessel/head_depth_comparison.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "designers/vessel/head_preset.h"
#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {

HeadStressSummary head_stress_summary(std::string name, const PolarFunction& head,
                                      const VesselLoad& load) {
  HeadStressSummary out;
  out.stresses = membrane_stresses(head, load);
  const StressProfile& profile = out.stresses;
  out.name = std::move(name);
  out.depth = head(std::numbers::pi / 2);
  double d[3];
  head.derivatives(0.0, 2, d);
  out.junction_curvature = polar_curvature(d[0], d[1], d[2]);
  bool first = true;
  for (const StressSample& s : profile.samples) {
    if (s.on_cylinder) continue;
    const double peak = std::max(std::abs(s.meridional_stress), std::abs(s.hoop_stress));
    if (first || peak > out.peak_stress) out.peak_stress = peak, out.peak_theta = s.theta;
    out.max_hoop_stress = first ? s.hoop_stress : std::max(out.max_hoop_stress, s.hoop_stress);
    out.min_hoop_stress = first ? s.hoop_stress : std::min(out.min_hoop_stress, s.hoop_stress);
    out.max_meridional_stress =
        first ? s.meridional_stress : std::max(out.max_meridional_stress, s.meridional_stress);
    first = false;
  }
  return out;
}

namespace {

std::string short_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

}  // namespace

DepthComparison standard_heads_of_depth(double depth, const VesselLoad& load) {
  const double a = load.radius;
  DepthComparison out;
  const HeadPreset ellipse{HeadKind::ellipsoidal, a / depth, 0.0, 0.0};
  out.references.push_back(head_stress_summary("ellipsoidal " + short_text(a / depth) + ":1",
                                               head_shape(ellipse, a).profile, load));
  for (const double knuckle_share : {0.06, 0.17}) {
    const std::string name = "torispherical, knuckle " + short_text(knuckle_share) + " D";
    try {
      const HeadPreset tori = torispherical_of_depth(a, depth, 2 * a * knuckle_share);
      out.references.push_back(head_stress_summary(
          name + ", crown " + short_text(tori.crown) + " mm", head_shape(tori, a).profile, load));
    } catch (const InputError& e) {
      out.missing.push_back(name + ": " + e.what());
    }
  }
  return out;
}

}  // namespace polarform
