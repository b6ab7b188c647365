#include "jobs/scan_cam/scan_cam_design_report.h"

#include <cmath>
#include <numbers>

#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using json = nlohmann::ordered_json;

json stats(const ErrorStats& e) { return json{{"rms", e.rms}, {"max", e.max}, {"count", e.count}}; }

// An angle of the scan's cam frame in the design's frame, degrees in [0, 360).
double design_degrees(double theta, double phase) {
  const double t = std::fmod(theta - phase, 2 * std::numbers::pi);
  return (t < 0 ? t + 2 * std::numbers::pi : t) * kDegreesPerRadian;
}

std::string law_name(const LawShape& shape) { return std::string(motion_law_name(shape.law)); }

json scca_json(const SccaParameters& p) { return json{{"b", p.b}, {"c", p.c}, {"d", p.d}}; }

json motion_json(const IdentifiedMotion& m, double phase, double noise) {
  const LawFit& f = m.law();
  json j{{"kind", segment_kind_name(m.kind)},
         {"law", law_name(f.shape)},
         {"from_deg", design_degrees(f.start, phase)},
         {"from_sd_deg", f.sd[0] * kDegreesPerRadian},
         {"to_deg", design_degrees(f.end, phase)},
         {"to_sd_deg", f.sd[1] * kDegreesPerRadian},
         {"lift_mm", std::abs(f.lift)},
         {"lift_sd_mm", f.sd[3]},
         {"rms_residual_mm", f.rms()},
         {"samples", f.count}};
  if (f.shape.law == MotionLaw::Scca) j["scca"] = scca_json(f.shape.scca);
  json candidates = json::array();
  for (std::size_t i = 0; i < m.candidates.size(); ++i) {
    const LawFit& c = m.candidates[i];
    json cj{{"law", law_name(c.shape)},
            {"rms_residual_mm", c.rms()},
            {"bic", m.bic[i]},
            {"delta_chi2", (c.rss - f.rss) / (noise * noise)},
            {"from_deg", design_degrees(c.start, phase)},
            {"to_deg", design_degrees(c.end, phase)},
            {"lift_mm", std::abs(c.lift)}};
    if (c.shape.law == MotionLaw::Scca) cj["scca"] = scca_json(c.shape.scca);
    candidates.push_back(cj);
  }
  j["candidates"] = candidates;
  json same = json::array();
  for (std::size_t i : m.indistinguishable) same.push_back(law_name(m.candidates[i].shape));
  j["indistinguishable_from"] = same;
  return j;
}

json program_json(const CamDesign& d) {
  json out = json::array();
  for (const SegmentSpec& s : d.segments) {
    json j{{"kind", segment_kind_name(s.kind)},
           {"from_deg", s.start * kDegreesPerRadian},
           {"to_deg", s.end * kDegreesPerRadian}};
    if (s.kind != SegmentKind::Dwell) {
      j["law"] = motion_law_name(s.law);
      j["lift_mm"] = s.lift;
      if (s.law == MotionLaw::Scca) j["scca"] = scca_json(s.scca);
    }
    out.push_back(j);
  }
  return out;
}

}  // namespace

const char* const kDerivativeNames[4] = {"s", "v", "a", "j"};

std::string law_label(const LawShape& shape) {
  std::string name(motion_law_name(shape.law));
  if (shape.law != MotionLaw::Scca) return name;
  return name + " (b " + format_trimmed(shape.scca.b, 3) + ", c " +
         format_trimmed(shape.scca.c, 3) + ", d " + format_trimmed(shape.scca.d, 3) + ")";
}

json design_json(const ScanCamJobResult& r) {
  if (!r.design) return json{{"recovered", false}, {"failure", r.design_failure}};
  const RecoveredDesign& d = *r.design;
  const double noise = r.scan.displacement.noise;
  json j{{"recovered", true},
         {"dwell_rule",
          {{"band_mm", d.segmentation.still_band},
           {"confidence", d.segmentation.confidence},
           {"rule",
            "a dwell is a run of at least 2 deg where the smoothed displacement stays within "
            "±3 standard errors (the band) over every ±1 deg window"}}},
         {"criterion",
          "least BIC = RSS/sigma^2 + k ln n (sigma: displacement noise; k = 4, 6 for SCCA); "
          "laws whose RSS is within 9 sigma^2 of the chosen one are indistinguishable"},
         {"phase_deg", d.phase * kDegreesPerRadian},
         {"phase_meaning", "design cam angle = scan cam angle − phase_deg"},
         {"base_radius_mm", d.design.base_radius}};
  json motions = json::array();
  for (const IdentifiedMotion& m : d.motions) motions.push_back(motion_json(m, d.phase, noise));
  j["segments"] = motions;
  j["program"] = program_json(d.design);
  const NominalComparison& c = d.deviation;
  j["redesign_deviation"] = {{"profile_normal_mm", stats(c.normal_stats)},
                             {"profile_radial_mm", stats(c.radial_stats)},
                             {"point_normal_mm", stats(c.point_normal_stats)},
                             {"point_radial_mm", stats(c.point_stats)},
                             {"s_mm", stats(c.svaj_stats[0])},
                             {"noise_mm", r.scan.contour_noise}};
  return j;
}

json resolution_json(const MotionResolution& res) {
  json j{
      {"rule",
       "resolved when max |derivative| >= 10 x the rms noise propagated from the scan "
       "noise through the displacement fit"},
      {"resolved_order", res.resolved_order},
      {"resolved_up_to", res.resolved_order >= 0 ? kDerivativeNames[res.resolved_order] : "none"},
      {"replicates", res.replicates}};
  for (std::size_t k = 0; k < 4; ++k) {
    const DerivativeResolution& d = res.derivatives[k];
    j["derivatives"][kDerivativeNames[k]] = {{"signal", d.signal},
                                             {"noise", d.noise},
                                             {"ratio", d.noise > 0 ? d.signal / d.noise : 0.0},
                                             {"resolved", d.resolved}};
  }
  return j;
}

}  // namespace polarform
