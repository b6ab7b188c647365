#include "designers/vessel/vessel_design.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "designers/vessel/head_volume.h"
#include "designers/vessel/polar_curvature.h"
#include "designers/vessel/target_placement.h"
#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;
// Slopes (rad) below this are the solver's round-off, not a kink worth a warning.
constexpr double kSlopeTolerance = 1e-6;
// Targets placed by s or φ: the synthesis is repeated until their θ move less than this (rad;
// 0.5 µm of meridian on a 500 mm head, above the ~1e-7 rad the SLSQP results scatter by).
constexpr double kPlacementTolerance = 1e-6;
constexpr int kMaxPlacementRounds = 60;

std::string short_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

std::string degrees(double rad) { return short_text(rad * 180 / kPi) + "°"; }

void check_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(std::string("vessel: ") + name + " " + to_text(value) + " " + unit +
                     ", expected > 0");
}

// κ of a head made of analytic pieces, piece by piece at about 0.5° steps: both one-sided values
// at every joint.
std::vector<CurvatureSample> piecewise_curvature(const HeadShape& shape) {
  std::vector<CurvatureSample> out;
  for (const PolarFunction& piece : shape.pieces) {
    const int count =
        std::max(1, static_cast<int>(std::ceil(360 * (piece.end - piece.start) / kPi)));
    const std::vector<CurvatureSample> s = sample_curvature(piece, count);
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

PresetComparison compare_with_preset(const HeadPreset& preset, const VesselDesign& design,
                                     const PolarFunction& head, const VesselLoad& load) {
  PresetComparison out;
  out.shape = head_shape(preset, design.radius);
  out.curvature = piecewise_curvature(out.shape);
  for (int i = 0; i <= 1440; ++i) {
    const double theta = kPi * i / 1440;
    const double deviation = std::abs(head(theta) - out.shape.profile(theta));
    if (deviation > out.max_deviation) out.max_deviation = deviation, out.deviation_angle = theta;
  }
  out.stresses = membrane_stresses(out.shape.profile, load, 181, out.shape.membrane_end());
  return out;
}

double derivative(const PolarFunction& f, double theta) {
  double d[2];
  f.derivatives(theta, 1, d);
  return d[1];
}

std::vector<std::string> warnings_for(const VesselSolution& s, const VesselDesign& design) {
  std::vector<std::string> out;
  if (std::abs(s.junction_radius - design.radius) > 1e-9 * design.radius)
    out.push_back("the head meets the cylinder at R(0) = " + short_text(s.junction_radius) +
                  " mm, not at the vessel radius " + short_text(design.radius) +
                  " mm; the cylinder continues the head");
  if (std::abs(s.junction_slope) > kSlopeTolerance)
    out.push_back("the head meets the cylinder at a kink of " + degrees(s.junction_slope) +
                  " (R'(0) = " + short_text(derivative(s.profile, 0.0)) + " mm/rad)");
  if (std::abs(s.apex_slope) > kSlopeTolerance)
    out.push_back("the revolved head has a cone point at the apex: the meridian meets the axis at " +
                  degrees(s.apex_slope) + " from the perpendicular (R'(90°) ≠ 0)");
  // A synthesised head that rings: inflections, and hoop stresses above the preset it replaces.
  if (!s.exact) {
    const auto inflected = std::find_if(s.curvature.begin(), s.curvature.end(),
                                        [](const CurvatureSample& c) { return c.kappa < 0.0; });
    if (inflected != s.curvature.end())
      out.push_back("the head has an inflection: κ < 0 from θ = " + degrees(inflected->theta) +
                    " (the meridian turns outwards; raise the smoothing or fewer ordinates)");
  }
  if (s.preset) {
    const auto max_hoop = [](const StressProfile& p) {
      double m = -1e300;
      for (const StressSample& k : p.samples)
        if (!k.on_cylinder) m = std::max(m, k.hoop_stress);
      return m;
    };
    const double design = max_hoop(s.stresses), preset = max_hoop(s.preset->stresses);
    if (design > preset * (1 + 1e-9))
      out.push_back("the head's largest hoop stress " + short_text(design) +
                    " MPa exceeds the preset's " + short_text(preset) + " MPa");
  }
  if (s.flat_plate)
    out.push_back(
        "membrane theory carries neither the knuckle's turn into the flat plate nor the "
        "plate (radius " +
        short_text(s.flat_plate->plate_radius) + " mm): its bending stress is " +
        short_text(s.flat_plate->clamped_edge) + " MPa at the edge if clamped, " +
        short_text(s.flat_plate->simply_supported_centre) +
        " MPa at the centre if simply supported (report.json flat_plate)");
  for (const CompressiveBand& band : s.stresses.compressive_hoop)
    out.push_back("compressive hoop stress down to " + short_text(band.min_hoop_stress) + " MPa " +
                  (band.theta_to > band.theta_from
                       ? "for θ from " + degrees(band.theta_from) + " to " +
                             degrees(band.theta_to) + " (meridian " + short_text(band.s_from) +
                             " to " + short_text(band.s_to) + " mm)"
                       : "at θ = " + degrees(band.theta_from) + " (meridian " +
                             short_text(band.s_from) + " mm) only"));
  return out;
}

// The head's geometry at the junction and the apex, its membrane stresses and the edge bending
// at its curvature jumps (an exact head's own; else the junction's), from out.profile.
void analyse_head(VesselSolution& out, const VesselLoad& load, double poisson) {
  double a[3], apex[2];
  out.profile.derivatives(0.0, 2, a);
  out.profile.derivatives(kPi / 2, 1, apex);
  out.depth = apex[0];
  out.junction_radius = a[0];
  out.junction_curvature = polar_curvature(a[0], a[1], a[2]);
  out.junction_slope = std::atan2(a[1], a[0]);
  out.apex_slope = std::atan2(apex[1], apex[0]);
  const double membrane_end = out.exact ? out.exact->shape.membrane_end() : kPi / 2;
  out.stresses = membrane_stresses(out.profile, load, 181, membrane_end);
  if (out.exact && out.exact->shape.plate_radius > 0.0)
    out.flat_plate =
        flat_plate_bending(out.exact->shape.plate_radius, load.thickness, load.pressure, poisson);
  HeadShape smooth;
  if (!out.exact) {
    smooth.pieces = {out.profile};
    smooth.profile = out.profile;
    smooth.jumps = {{0.0, 0.0, out.junction_curvature}};
  }
  out.edge_bending = edge_bending(out.exact ? out.exact->shape : smooth, load, poisson);
}

// The preset head itself: its exact meridian, closed-form curvature and stresses (no synthesis).
VesselSolution solve_exact_head(const VesselDesign& design, const VesselLoad& load) {
  if (!design.preset) throw InputError("vessel: an exact head needs a <head preset>");
  if (!design.targets.empty())
    throw InputError(
        "vessel: an exact head takes no curvature targets; ask for design=\"curvature\" "
        "to synthesise a head from them");
  VesselSolution out;
  out.exact = exact_head(*design.preset, design.radius);
  const HeadShape& shape = out.exact->shape;
  out.profile = shape.profile;
  out.curvature = piecewise_curvature(shape);
  analyse_head(out, load, design.poisson);
  out.warnings = warnings_for(out, design);
  return out;
}

// Bae 2002, §5.2: synthesis, then the analyses of the result (and of the preset, if any).
VesselSolution solve_curvature_design(const VesselDesign& design, const VesselLoad& load) {
  if (design.targets.empty() && !design.preset)
    throw InputError("vessel: no curvature targets and no head preset to take them from");

  SynthesisProblem problem;
  problem.length_unit = design.radius;
  problem.end_a = design.end_a.value_or(EndCondition::thesis_default(design.radius));
  problem.end_b = design.end_b.value_or(EndCondition::thesis_default(design.radius));
  problem.settings = design.synthesis;
  problem.depth = design.depth;
  problem.volume = design.volume;
  problem.targets = design.targets;
  if (problem.targets.empty())
    problem.targets =
        preset_targets(head_shape(*design.preset, design.radius), design.preset_targets);

  // Targets by arc length or meridian angle: placed on the start circle, then moved halfway to
  // their places on every result until their polar angles stop moving (a damped fixed-point
  // iteration; the smoothing re-chosen each round).
  VesselSolution out;
  place_targets_on_circle(problem.targets, problem.end_a.r.value_or(design.radius));
  const bool placed =
      std::any_of(problem.targets.begin(), problem.targets.end(),
                  [](const CurvatureTarget& t) { return t.place != TargetPlace::polar_angle; });
  std::optional<double> hint;
  for (int round = 1;; ++round) {
    out.synthesis = synthesize_with_chosen_smoothing(problem, out.smoothing, hint);
    hint = out.synthesis.smoothing;
    out.placement_rounds = round;
    if (!placed) break;
    const std::vector<CurvatureTarget> before = problem.targets;
    const double moved = place_targets(problem.targets, head_polar_function(out.synthesis.profile));
    for (std::size_t k = 0; k < before.size(); ++k)  // damped: undamped rounds may oscillate
      problem.targets[k].theta = 0.5 * (before[k].theta + problem.targets[k].theta);
    if (moved < kPlacementTolerance) break;
    if (round == kMaxPlacementRounds)
      throw NumericalError("vessel: the targets given by s or φ still move by " + degrees(moved) +
                           " after " + std::to_string(round) +
                           " rounds of synthesis; give them by polar angle θ");
  }
  out.profile = head_polar_function(out.synthesis.profile);
  out.curvature = sample_curvature(out.profile, 360);
  out.measures_of_design = polar_head_measures(out.profile);
  analyse_head(out, load, design.poisson);
  if (design.preset) out.preset = compare_with_preset(*design.preset, design, out.profile, load);
  out.warnings = warnings_for(out, design);
  return out;
}

// The head of the asked depth with the smallest peak membrane stress, and the standard heads of
// that depth beside it.
VesselSolution solve_minimum_stress(const VesselDesign& design, const VesselLoad& load) {
  if (!design.targets.empty())
    throw InputError(
        "vessel: a minimum-stress head takes no curvature targets; ask for design=\"curvature\" "
        "to synthesise a head from them");
  if (!design.depth && !design.preset)
    throw InputError(
        "vessel: a minimum-stress head needs <head depth> or a preset to take it from");
  const double depth =
      design.depth ? *design.depth : head_shape(*design.preset, design.radius).depth;
  VesselSolution out;
  MinimumStressDesign m;
  m.settings.junction_curvature = design.junction_kappa;
  m.head = minimum_peak_stress_head(design.radius, depth, m.settings);
  out.profile = head_polar_function(m.head.profile);
  out.curvature = sample_curvature(out.profile, 360);
  out.measures_of_design = polar_head_measures(out.profile);
  analyse_head(out, load, design.poisson);
  m.stresses = head_stress_summary("minimum-stress head", out.profile, load);
  m.same_depth = standard_heads_of_depth(depth, load);
  out.minimum_stress = std::move(m);
  if (design.preset) out.preset = compare_with_preset(*design.preset, design, out.profile, load);
  out.warnings = warnings_for(out, design);
  return out;
}

}  // namespace

const char* head_design_name(HeadDesign design) {
  switch (design) {
    case HeadDesign::exact:
      return "exact";
    case HeadDesign::minimum_stress:
      return "minimum-stress";
    case HeadDesign::curvature:
      break;
  }
  return "curvature";
}

PolarFunction head_polar_function(const BSplineFunction& R) {
  PolarFunction f;
  f.start = 0.0;
  f.end = kPi;
  f.breakpoints = {kPi / 2};
  f.derivatives = [R](double theta, int d, double* out) {
    const Eigen::VectorXd v = R.derivatives(theta, d);
    for (int k = 0; k <= d; ++k) out[k] = v(k);
  };
  f.exact = R;
  return f;
}

std::vector<CurvatureSample> sample_curvature(const PolarFunction& f, int count) {
  if (count < 1)
    throw InputError("curvature samples: count " + std::to_string(count) + ", expected >= 1");
  std::vector<CurvatureSample> out;
  for (int i = 0; i <= count; ++i) {
    const double theta = i == count ? f.end : f.start + (f.end - f.start) * i / count;
    double d[3];
    f.derivatives(theta, 2, d);
    out.push_back({theta, polar_curvature(d[0], d[1], d[2]), d[0], d[1], d[2]});
  }
  return out;
}

// The head (exact, synthesised: Bae 2002, §5.2, or of minimum peak stress) with its analyses, then
// the code check and the measures.
VesselSolution solve_vessel(const VesselDesign& design) {
  check_positive(design.radius, "radius", "mm");
  check_positive(design.length, "length", "mm");
  check_positive(design.thickness, "thickness", "mm");
  check_positive(design.pressure, "pressure", "MPa");
  const VesselLoad load{design.radius, design.length, design.thickness, design.pressure};
  VesselSolution out = design.head_design == HeadDesign::exact ? solve_exact_head(design, load)
                       : design.head_design == HeadDesign::minimum_stress
                           ? solve_minimum_stress(design, load)
                           : solve_curvature_design(design, load);
  if (out.exact)
    out.measures = vessel_measures(*design.preset, design.radius, design.length, design.thickness,
                                   design.density, design.straight_flange);
  if (design.code) {
    out.code = check_vessel_code(*design.code, design.radius, design.thickness, design.pressure,
                                 out.exact ? design.preset : std::nullopt);
    for (const CodeCheck* c : {&out.code->shell, out.code->head ? &*out.code->head : nullptr})
      if (c) out.warnings.insert(out.warnings.end(), c->warnings.begin(), c->warnings.end());
    if (!out.code->thickness_sufficient)
      out.warnings.push_back("the wall of " + short_text(design.thickness) +
                             " mm is thinner than the code requires (report.json code)");
  }
  return out;
}

}  // namespace polarform
