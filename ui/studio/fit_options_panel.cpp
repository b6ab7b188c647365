#include "ui/studio/fit_options_panel.h"

#include <imgui.h>

#include <array>
#include <string_view>

#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

// A checkbox that sets or clears `value` (starting from `fallback`) and, when set, its three
// coordinates; true when either changed.
bool optional_vector(const char* label, std::optional<Eigen::Vector3d>& value,
                     const Eigen::Vector3d& fallback) {
  bool on = value.has_value();
  ImGui::PushID(label);
  bool changed = ImGui::Checkbox("##on", &on);
  if (changed) value = on ? std::optional<Eigen::Vector3d>(fallback) : std::nullopt;
  ImGui::SameLine();
  if (value) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12);
    changed |= ImGui::InputScalarN(label, ImGuiDataType_Double, value->data(), 3, nullptr, nullptr,
                                   "%.4g");
  } else {
    ImGui::TextDisabled("%s: estimated", label);
  }
  ImGui::PopID();
  return changed;
}

}  // namespace

bool draw_fit_options(FitSettings& s) {
  bool changed = false;
  ImGui::PushItemWidth(ImGui::GetFontSize() * 9);
  static constexpr std::array<std::string_view, 4> kMethods = {
      "automatic", "polar profile", "spherical", "cylindrical"};  // FitJobMethod's order
  changed |= combo("method", s.method, kMethods);
  help_marker(
      "Automatic: a planar cloud is a profile, fitted by a polar curve about its centre (Bae "
      "2002, ch. 2); otherwise sphere-like quadrics are fitted spherically, cylinder-like ones "
      "cylindrically, and where the type does not decide both are fitted and the smaller error "
      "wins (§4.3).");
  changed |= input_int("degree along u", s.degree_u, 1, 7);
  changed |= input_int("degree along v", s.degree_v, 1, 7);
  changed |= ImGui::Checkbox("refine to a tolerance", &s.use_tolerance);
  if (s.use_tolerance) {
    changed |= log_slider("distance [mm]", s.tolerance, 1e-5, 10.0, "%.3g");
    static constexpr std::array<std::string_view, 4> kMeasures = {"max", "99th percentile",
                                                                  "95th percentile", "RMS"};
    changed |= combo("of the", s.measure, kMeasures);
    help_marker(
        "The statistic of the true point-to-surface distance the tolerance bounds. Scan noise "
        "makes the "
        "max unreachable; the 99th percentile ignores the worst 1 % of the points.");
  } else {
    changed |= ImGui::Checkbox("net chosen by the data", &s.automatic_net);
    help_marker(
        "Nets grown until generalised cross-validation stops improving (the residual reaches the "
        "noise), at most one coefficient per 4 points (as polarform fit without --ctrl).");
    if (!s.automatic_net) {
      changed |= input_int("control values u", s.size_u, 2, 200);
      changed |= input_int("control values v", s.size_v, 2, 200);
    }
  }
  static constexpr std::array<std::string_view, 3> kFairness = {"fixed λ", "relative λ", "GCV"};
  changed |= combo("fairness", s.fairness, kFairness);
  if (s.fairness != 2) changed |= log_slider("λ", s.fairness_weight, 1e-12, 1.0, "%.2g");
  changed |= ImGui::Checkbox("quasi-uniform quartic base arcs", &s.quartic_base);
  static constexpr std::array<std::string_view, 3> kClosure = {"automatic", "open", "closed"};
  changed |= combo("closure in θ", s.closure, kClosure);
  static constexpr std::array<std::string_view, 5> kPoles = {"automatic", "none", "G0 point",
                                                             "G1 point", "cap surface"};
  changed |= combo("poles (spherical)", s.pole, kPoles);
  static constexpr std::array<std::string_view, 3> kRevolution = {"F-test", "always", "never"};
  changed |= combo("exact revolution", s.revolution, kRevolution);
  help_marker(
      "Whether F is made constant around the axis (an exact surface of revolution, sphere-like "
      "form or circle): decided by an F-test of F(u) against F(u, v) at the 0.1 % level, or "
      "always, or never (as --revolution auto|yes|no of polarform fit).");
  changed |= ImGui::Checkbox("reject outliers", &s.reject_outliers);
  help_marker(
      "Points more than 8 robust σ off the fit are left out of it and the fit repeated until they "
      "stay the same (as --reject-outliers of polarform fit). Unchecked, a cloud with a few such "
      "points is refused with their count.");
  ImGui::PopItemWidth();
  changed |= optional_vector("frame origin [mm]", s.center, Eigen::Vector3d::Zero());
  changed |= optional_vector("frame axis k", s.axis, Eigen::Vector3d::UnitZ());
  help_marker(
      "Unchecked, the frame is estimated from the cloud (general quadric fit, Bae 2002, §4.3). "
      "Checked, the given origin and axis are used instead, as --center and --axis of "
      "polarform fit.");
  return changed;
}

}  // namespace polarform::studio
