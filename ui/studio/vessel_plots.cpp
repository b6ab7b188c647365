#include "ui/studio/vessel_plots.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/colors.h"

namespace polarform::studio {
namespace {

PlotLine line(const char* label, const XYSeries& s, int palette, float thickness = 2.0f) {
  return {label, s.x, s.y, palette_color(palette), thickness};
}

}  // namespace

void VesselPlots::draw_meridian(const VesselResults& r, ImVec2 size) {
  const ImVec2 min = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("meridian", size);
  meridian_view_.handle_input(ImGui::IsItemHovered(), ImGui::IsItemActive());
  const ImVec2 max(min.x + size.x, min.y + size.y);
  const double radius = r.project.design.radius;
  double depth = 0.0;
  for (std::size_t i = 0; i < r.radius.x.size(); ++i)
    depth = std::max(depth, r.radius.y[i] * std::sin(r.radius.x[i] * kRadiansPerDegree));
  const double below = 0.35 * radius;  // a stretch of the cylinder below the junction plane
  meridian_view_.set_canvas(min, max,
                            Box2{-1.1 * radius, -below, 1.1 * radius, depth * 1.1 + 0.05 * radius});
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(min, max, color::background);
  dl->PushClipRect(min, max, true);
  const auto at = [&](double x, double z) { return meridian_view_.to_screen(x, z); };
  const auto meridian = [&](const XYSeries& s, ImU32 c, float w) {
    std::vector<ImVec2> pts;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double t = s.x[i] * kRadiansPerDegree;
      pts.push_back(at(s.y[i] * std::cos(t), s.y[i] * std::sin(t)));
    }
    dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), c, 0, w);
  };
  dl->AddLine(at(-1.2 * radius, 0), at(1.2 * radius, 0), color::grid);  // junction plane
  dl->AddLine(at(0, -below), at(0, depth * 1.15), color::grid);         // axis
  const double ra = r.solution.junction_radius;
  dl->AddLine(at(ra, 0), at(ra, -below), color::text, 2.0f);  // cylinder
  dl->AddLine(at(-r.radius.y.back(), 0), at(-r.radius.y.back(), -below), color::text, 2.0f);
  if (r.preset_radius) meridian(*r.preset_radius, palette_color(1, 0.8f), 1.0f);
  meridian(r.radius, palette_color(0), 2.0f);
  dl->PopClipRect();
  dl->AddRect(min, max, color::frame);
  dl->AddText(ImVec2(min.x + 6, min.y + 4), color::text, "meridian (x, z) [mm]");
  dl->AddText(ImVec2(min.x + 6, min.y + 4 + ImGui::GetFontSize()), palette_color(0), "design");
  if (r.preset_radius)
    dl->AddText(ImVec2(min.x + 6, min.y + 4 + 2 * ImGui::GetFontSize()), palette_color(1),
                r.solution.preset->shape.name.c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("wheel: zoom · drag: pan · double-click: fit");
}

void VesselPlots::draw_curvature(const VesselResults& r, ImVec2 size) {
  PlotSpec spec;
  spec.id = "curvature";
  spec.y_label = "κ [1/mm]";
  spec.x_label = "θ [°]";
  spec.title = "curvature";
  spec.x_extent = AxisRange{0, 180};
  if (r.preset_kappa) spec.lines.push_back(line("preset", *r.preset_kappa, 1, 1.0f));
  spec.lines.push_back(line("design κ(θ)", r.kappa, 0, 2.0f));
  for (std::size_t i = 0; i < r.targets.x.size(); ++i)
    spec.points.push_back({r.targets.x[i], r.targets.y[i],
                           "target κ = " + number_text(r.targets.y[i]) + " 1/mm, achieved " +
                               number_text(r.achieved.y[i]),
                           palette_color(2), r.targets.x.size() > 24});
  spec.markers.push_back({90.0, "apex", 0, false});
  draw_plot(spec, curvature_x_, curvature_y_, size);
}

void VesselPlots::draw_residuals(const VesselResults& r, ImVec2 size) {
  PlotSpec spec;
  spec.id = "residuals";
  spec.y_label = "κ − κₖ [1/mm]";
  spec.x_label = "θ [°]";
  spec.title = "residual at the targets";
  spec.x_extent = AxisRange{0, 180};
  spec.lines.push_back(line("residual", r.residuals, 2, 1.0f));
  for (std::size_t i = 0; i < r.residuals.x.size(); ++i)
    spec.points.push_back({r.residuals.x[i], r.residuals.y[i], "", palette_color(2), true});
  spec.levels.push_back({0.0, "", color::muted});
  draw_plot(spec, residual_x_, residual_y_, size);
}

void VesselPlots::draw_stresses(const VesselResults& r, ImVec2 size) {
  PlotSpec spec;
  spec.id = "stresses";
  spec.y_label = "stress [MPa]";
  spec.x_label = "meridian arc length from junction A [mm] (negative: cylinder)";
  spec.title = "membrane stresses";
  if (r.preset_meridional) {
    spec.lines.push_back({"preset meridional", r.preset_meridional->x, r.preset_meridional->y,
                          palette_color(0, 0.45f), 1.0f});
    spec.lines.push_back(
        {"preset hoop", r.preset_hoop->x, r.preset_hoop->y, palette_color(1, 0.45f), 1.0f});
  }
  spec.lines.push_back(line("meridional", r.meridional, 0, 2.0f));
  spec.lines.push_back(line("hoop", r.hoop, 1, 2.0f));
  for (const CompressiveBand& band : r.solution.stresses.compressive_hoop)
    spec.bands.push_back({band.s_from, band.s_to, color::error_band});
  spec.levels.push_back({0.0, "", color::muted});
  spec.markers.push_back({0.0, "junction A", 0, false});
  draw_plot(spec, stress_x_, stress_y_, size);
}

}  // namespace polarform::studio
