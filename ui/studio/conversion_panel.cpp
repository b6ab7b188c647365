#include "ui/studio/conversion_panel.h"

#include <array>
#include <string_view>

#include "jobs/cam/cam_plots.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/colors.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

void row(const char* name, const std::string& value, ImU32 colour = 0) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  if (colour) ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextUnformatted(value.c_str());
  if (colour) ImGui::PopStyleColor();
}

}  // namespace

bool ConversionPanel::draw_settings(ConversionOptions& o) {
  bool changed = false;
  ImGui::PushItemWidth(ImGui::GetFontSize() * 9);
  changed |= log_slider("tolerance [mm]", o.tolerance, 1e-6, 1e-1, "%.2g");
  help_marker(
      "Bound on the measured radial error of the NURBS profile. The converter measures the error "
      "of the "
      "final curve densely and adds arcs until it is met (DESIGN §4.3).");
  static constexpr std::array<std::string_view, 2> kBases = {"quasi-uniform quartic",
                                                             "rational quadratic (RQB)"};
  int base = o.base == ArcKind::quartic ? 0 : 1;
  if (combo("base arcs", base, kBases)) {
    o.base = base == 0 ? ArcKind::quartic : ArcKind::rqb;
    changed = true;
  }
  if (o.base == ArcKind::quartic) {
    static constexpr std::array<std::string_view, 2> kAlpha = {"minimax", "as printed (5.2)"};
    int alpha = o.alpha == AlphaRule::minimax ? 0 : 1;
    if (combo("α rule", alpha, kAlpha)) {
      o.alpha = alpha == 0 ? AlphaRule::minimax : AlphaRule::printed;
      changed = true;
    }
  }
  static constexpr std::array<std::string_view, 3> kCompactions = {
      "refit (fewest control points)", "knot removal", "none (exactly F·B)"};
  int compaction = o.compaction == Compaction::refit ? 0 : o.compaction == Compaction::none ? 2 : 1;
  if (combo("compaction", compaction, kCompactions)) {
    o.compaction = compaction == 0   ? Compaction::refit
                   : compaction == 2 ? Compaction::none
                                     : Compaction::full;
    changed = true;
  }
  help_marker(
      "How the product C = F·B is made compact within the tolerance: refitted by a B-spline of "
      "degree 3-6 with knots placed by need (the project's compaction=\"refit\"), its knots "
      "removed (NURBS Book A5.8), or left as the product (dwells exact circular arcs).");
  changed |= drag_number("function share", o.function_share, 0.005, 0.01, 0.99, "%.2f");
  help_marker(
      "The share of the tolerance allowed for representing R(θ) as a B-spline F; the arcs get the "
      "rest.");
  ImGui::PopItemWidth();
  return changed;
}

void ConversionPanel::draw_result(const PolarConversion* c, int degree, int control_points,
                                  const std::string& error, bool stale) {
  if (!error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
  }
  if (!c) return;
  if (stale) ImGui::TextDisabled("(result of an earlier design)");
  if (!ImGui::BeginTable("conversion", 2,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  const auto um = [](double mm) { return number_text(to_micrometres(mm)) + " µm"; };
  row("arcs", std::to_string(c->arcs.size()));
  row("degree",
      std::to_string(degree) + (c->curve.is_rational() ? " (rational)" : " (polynomial)"));
  row("control points", std::to_string(control_points));
  std::string steps;  // the conversion's steps, e.g. "product 110 → refit 22"
  for (const ConversionStep& step : c->steps)
    steps += (steps.empty() ? "" : " → ") + step.name + " " + std::to_string(step.control_points);
  row("steps", steps);
  row("max radial error", um(c->max_radial_error) + " (tolerance " + um(c->tolerance) + ")",
      c->max_radial_error <= c->tolerance ? color::ok : color::error);
  row("max normal error", um(c->max_normal_error));
  row("worst at polar angle", number_text(degrees_in_turn(c->worst_angle)) + "°");
  row("tangent jump at junctions", degrees_text(c->max_tangent_jump));
  row("error budget F / arcs", (c->function_exact ? "exact, " : "") + um(c->function_error) +
                                   " / " + um(c->synchronization_error));
  ImGui::EndTable();
}

void ConversionPanel::draw_error_plot(const CamConversionStage& c, std::uint64_t revision,
                                      ImVec2 size) {
  if (ImGui::Checkbox("log scale", &log_scale_) || !figure_ || figure_revision_ != revision) {
    figure_ = conversion_error_figure(c, log_scale_);
    figure_revision_ = revision;
  }
  size.y -= ImGui::GetFrameHeightWithSpacing();
  draw_figure("conversion error", *figure_, view_, size);
}

}  // namespace polarform::studio
