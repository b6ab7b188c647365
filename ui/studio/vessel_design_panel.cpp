#include "ui/studio/vessel_design_panel.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

#include "src/units.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

// One optional condition value: a checkbox imposes it.
bool optional_value(const char* label, std::optional<double>& v, double fallback) {
  bool on = v.has_value();
  bool changed = false;
  ImGui::PushID(label);
  if (ImGui::Checkbox("##on", &on)) {
    v = on ? std::optional<double>(v.value_or(fallback)) : std::nullopt;
    changed = true;
  }
  ImGui::SameLine();
  ImGui::BeginDisabled(!on);
  double value = v.value_or(fallback);
  if (drag_number(label, value, 0.01, -1e7, 1e7, "%.5g") && on) {
    v = value;
    changed = true;
  }
  ImGui::EndDisabled();
  ImGui::PopID();
  return changed;
}

}  // namespace

bool VesselDesignPanel::draw(VesselProject& p) {
  bool changed = false;
  VesselDesign& d = p.design;
  ImGui::PushItemWidth(ImGui::GetFontSize() * 9);
  section("Vessel");
  changed |= drag_number("cylinder radius [mm]", d.radius, 1.0, 0.0, 1e6, "%.3f");
  changed |= drag_number("cylinder length [mm]", d.length, 1.0, 0.0, 1e7, "%.3f");
  changed |= drag_number("wall thickness [mm]", d.thickness, 0.05, 0.0, 1e5, "%.3f");
  changed |= drag_number("pressure [MPa]", d.pressure, 0.01, 0.0, 1e4, "%.3f");
  section("Head preset");
  changed |= draw_preset(d);
  section("Head design");
  changed |= draw_design(d);
  // Only a synthesised head uses the end conditions and the synthesis's settings.
  const bool synthesised = d.head_design == HeadDesign::curvature;
  section("End conditions");
  if (!synthesised) ImGui::TextDisabled("not used by an %s head", head_design_name(d.head_design));
  ImGui::BeginDisabled(!synthesised);
  changed |= draw_end("junction A (θ = 0°)", d.end_a, d.radius);
  changed |= draw_end("junction B (θ = 180°)", d.end_b, d.radius);
  section("Synthesis");
  changed |= draw_synthesis(d.synthesis);
  ImGui::EndDisabled();
  section("Conversion");
  changed |= log_slider("tolerance [mm]", p.tolerance, 1e-6, 1.0, "%.2g");
  ImGui::PopItemWidth();
  return changed;
}

bool VesselDesignPanel::draw_preset(VesselDesign& d) {
  bool changed = false;
  static constexpr std::array<std::string_view, 6> kNames = {
      "none", "hemispherical", "ellipsoidal", "torispherical", "conical", "flat"};
  int kind = d.preset ? static_cast<int>(d.preset->kind) + 1 : 0;
  if (combo("preset", kind, kNames)) {
    if (kind == 0) {
      d.preset.reset();
    } else {
      HeadPreset preset = kind == 3 ? torispherical_100_6(d.radius) : HeadPreset{};
      preset.kind = static_cast<HeadKind>(kind - 1);
      if (preset.kind == HeadKind::conical)  // a 30° toriconical head, knuckle 6 % of D
        preset.half_angle = std::numbers::pi / 6, preset.knuckle = 0.12 * d.radius;
      if (preset.kind == HeadKind::flat) preset.knuckle = 0.12 * d.radius;
      d.preset = preset;
    }
    changed = true;
  }
  if (!d.preset) return changed;
  HeadPreset& h = *d.preset;
  if (h.kind == HeadKind::ellipsoidal)
    changed |= drag_number("radius / depth", h.ratio, 0.01, 0.05, 100.0, "%.3f");
  if (h.kind == HeadKind::torispherical) {
    changed |= drag_number("crown radius [mm]", h.crown, 1.0, 0.0, 1e7, "%.3f");
    changed |= drag_number("knuckle radius [mm]", h.knuckle, 0.5, 0.0, 1e7, "%.3f");
    if (ImGui::Button("100 %/6 %")) {
      h = torispherical_100_6(d.radius);
      changed = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("80 %/10 %")) {
      h = torispherical_80_10(d.radius);
      changed = true;
    }
  }
  if (h.kind == HeadKind::flat)
    changed |= drag_number("knuckle radius [mm]", h.knuckle, 0.5, 0.01, 1e7, "%.3f");
  if (h.kind == HeadKind::conical) {
    double degrees = to_degrees(h.half_angle);
    if (drag_number("half apex angle [deg]", degrees, 0.1, 1.0, 89.0, "%.2f")) {
      h.half_angle = to_radians(degrees);
      changed = true;
    }
    changed |= drag_number("knuckle radius [mm]", h.knuckle, 0.5, 0.0, 1e7, "%.3f");
  }
  if (d.head_design != HeadDesign::curvature) return changed;
  changed |= input_int("sampled targets", d.preset_targets, 1, 2000);
  help_marker(
      "Without curvature targets the synthesis fits this many samples of the preset's curvature; "
      "with targets the preset is only compared.");
  return changed;
}

bool VesselDesignPanel::draw_design(VesselDesign& d) {
  bool changed = false;
  static constexpr std::array<std::string_view, 3> kDesigns = {"curvature", "exact",
                                                               "minimum-stress"};
  static constexpr std::array<HeadDesign, 3> kValues = {HeadDesign::curvature, HeadDesign::exact,
                                                        HeadDesign::minimum_stress};
  int design =
      static_cast<int>(std::find(kValues.begin(), kValues.end(), d.head_design) - kValues.begin());
  if (combo("design", design, kDesigns)) {
    d.head_design = kValues[design];
    if (d.head_design == HeadDesign::minimum_stress && !d.preset && !d.depth)
      d.depth = d.radius / 2;  // the 2:1 depth: a minimum-stress head needs one
    changed = true;
  }
  help_marker(
      "exact: the preset head itself, as rational quadratic arcs (degree 2). curvature: a head "
      "synthesised from curvature targets under the end conditions. minimum-stress: the head of "
      "the depth below (or the preset's) with the smallest peak membrane stress, compared with "
      "the standard heads of that depth.");
  if (d.head_design == HeadDesign::curvature) {
    changed |= optional_value("depth R(90°) [mm]", d.depth, d.radius / 2);
    help_marker("Checked: the synthesis holds the head's depth R(90°) to this.");
    // The 2:1 ellipsoidal head's (2/3)π a²(a/2) as the first value offered.
    changed |=
        optional_value("volume [mm³]", d.volume, std::numbers::pi / 3 * std::pow(d.radius, 3));
    help_marker(
        "Checked: the synthesis holds the volume the head encloses with its junction plane to "
        "this, (2π/3)∫R³cosθ dθ over 0..90° (a cubic equality constraint).");
  }
  if (d.head_design != HeadDesign::minimum_stress) return changed;
  const double preset_depth = d.preset ? head_shape(*d.preset, d.radius).depth : d.radius / 2;
  changed |= optional_value("depth [mm]", d.depth, preset_depth);
  help_marker("Unchecked: the preset's depth.");
  changed |= optional_value("junction κ [1/mm]", d.junction_kappa, 0.0);
  help_marker(
      "The meridian's curvature where it meets the cylinder; unchecked: free, chosen by "
      "the optimiser; 0: curvature-continuous with the cylinder.");
  return changed;
}

bool VesselDesignPanel::draw_end(const char* title, std::optional<EndCondition>& end,
                                 double radius) {
  bool changed = false;
  ImGui::PushID(title);
  bool custom = end.has_value();
  if (ImGui::Checkbox(title, &custom)) {
    end = custom ? std::optional<EndCondition>(EndCondition::thesis_default(radius)) : std::nullopt;
    changed = true;
  }
  if (!custom) {
    ImGui::SameLine();
    ImGui::TextDisabled("default: R = radius, R' = R'' = 0");
  } else {
    ImGui::Indent();
    changed |= optional_value("R [mm]", end->r, radius);
    changed |= optional_value("R' [mm/rad]", end->dr, 0.0);
    changed |= optional_value("R'' [mm/rad²]", end->ddr, 0.0);
    ImGui::Unindent();
  }
  ImGui::PopID();
  return changed;
}

bool VesselDesignPanel::draw_synthesis(SynthesisSettings& s) {
  bool changed = false;
  changed |= input_int("degree", s.degree, 3, 9);
  changed |= input_int("ordinates", s.ordinates, 4, 200);
  static constexpr std::array<std::string_view, 3> kRules = {"auto (shape-preserving)", "tolerance",
                                                             "fixed"};
  static constexpr std::array<SmoothingRule, 3> kRuleValues = {
      SmoothingRule::shape_preserving, SmoothingRule::tolerance, SmoothingRule::fixed};
  int rule = static_cast<int>(std::find(kRuleValues.begin(), kRuleValues.end(), s.smoothing_rule) -
                              kRuleValues.begin());
  if (combo("smoothing", rule, kRules)) {
    s.smoothing_rule = kRuleValues[rule];
    if (s.smoothing_rule == SmoothingRule::tolerance && !(s.kappa_tolerance > 0.0))
      s.kappa_tolerance = 1e-5;
    changed = true;
  }
  help_marker(
      "auto: the closest fit whose curvature has no turning point or inflection the targets lack. "
      "tolerance: the smoothest head that meets every target within the κ tolerance. fixed: the "
      "weight λ below.");
  if (s.smoothing_rule == SmoothingRule::fixed)
    changed |= log_slider("smoothing λ", s.smoothing, 1e-12, 1e2, "%.2g");
  if (s.smoothing_rule == SmoothingRule::tolerance)
    changed |= log_slider("κ tolerance [1/mm]", s.kappa_tolerance, 1e-9, 1e-2, "%.2g");
  changed |= ImGui::Checkbox("symmetric about 90°", &s.symmetric);
  changed |= input_int("max iterations", s.max_iterations, 10, 100000);
  return changed;
}

}  // namespace polarform::studio
