#include "ui/studio/conversion_panel.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

#include "ui/studio/colors.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

void row(const char* name, const char* value, ImU32 colour = 0) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  if (colour) ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextUnformatted(value);
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
  changed |= drag_number("function share", o.function_share, 0.005, 0.01, 0.99, "%.2f");
  help_marker(
      "The share of the tolerance allowed for representing R(θ) as a B-spline F; the arcs get the "
      "rest.");
  ImGui::PopItemWidth();
  return changed;
}

void ConversionPanel::draw_result(const CamConversion* c, const std::string& error, bool stale) {
  if (!error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
  }
  if (!c) return;
  if (stale) ImGui::TextDisabled("(result of an earlier design)");
  const ConversionSummary& s = c->summary;
  if (!ImGui::BeginTable("conversion", 2,
                         ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%d", s.arcs);
  row("arcs", buffer);
  std::snprintf(buffer, sizeof buffer, "%d (%s)", s.degree, s.rational ? "rational" : "polynomial");
  row("degree", buffer);
  std::snprintf(buffer, sizeof buffer, "%d", s.control_points);
  row("control points", buffer);
  std::snprintf(buffer, sizeof buffer, "%.4g µm (tolerance %.4g µm)", s.max_radial_error * 1e3,
                s.tolerance * 1e3);
  row("max radial error", buffer, s.max_radial_error <= s.tolerance ? color::ok : color::error);
  std::snprintf(buffer, sizeof buffer, "%.4g µm", s.max_normal_error * 1e3);
  row("max normal error", buffer);
  std::snprintf(buffer, sizeof buffer, "%.2f°",
                std::remainder(s.worst_angle, 2 * std::numbers::pi) * kDegreesPerRadian);
  row("worst at polar angle", buffer);
  std::snprintf(buffer, sizeof buffer, "%.3g rad", s.max_tangent_jump);
  row("tangent jump at junctions", buffer);
  std::snprintf(buffer, sizeof buffer, "%s%.3g µm / %.3g µm", s.function_exact ? "exact, " : "",
                s.function_error * 1e3, s.synchronization_error * 1e3);
  row("error budget F / arcs", buffer);
  ImGui::EndTable();
}

void ConversionPanel::draw_error_plot(const CamConversion& c, ImVec2 size) {
  ImGui::Checkbox("log scale", &log_scale_);
  PlotSpec spec;
  spec.id = "conversion error";
  spec.title = "measured radial error of the NURBS profile";
  spec.y_label = "|ρ − R(ψ)| [µm]";
  spec.x_label = "polar angle ψ [°]";
  spec.log_y = log_scale_;
  spec.x_extent = AxisRange{0.0, 360.0};
  spec.lines.push_back({"radial error", c.error_angle_deg, c.error_um, palette_color(2), 2.0f});
  spec.levels.push_back({c.summary.tolerance * 1e3, "tolerance", color::error});
  for (double j : c.junctions_deg)
    spec.markers.push_back({j, "arc junction", IM_COL32(150, 150, 150, 110), false});
  size.y -= ImGui::GetFrameHeightWithSpacing();
  draw_plot(spec, x_view_, y_view_, size);
}

}  // namespace polarform::studio
