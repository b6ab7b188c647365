#include "ui/studio/cam_summary_panel.h"

#include <imgui.h>

#include <cmath>

#include "ui/studio/colors.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

void row(const char* name, const char* value, bool bad = false) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  if (bad) ImGui::PushStyleColor(ImGuiCol_Text, color::error);
  ImGui::TextUnformatted(value);
  if (bad) ImGui::PopStyleColor();
}

std::string at(double value, const char* unit, double theta) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.4g %s at %.2f°", value, unit, theta * kDegreesPerRadian);
  return buffer;
}

}  // namespace

void draw_cam_summary(const CamResults& r, const CamViewSettings& view) {
  if (!ImGui::BeginTable("summary", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.4g mm", r.program->stroke());
  row("stroke", buffer);
  row("max |v|", at(r.extrema.velocity.value, "mm/rad", r.extrema.velocity.theta).c_str());
  row("max |a|", at(r.extrema.acceleration.value, "mm/rad²", r.extrema.acceleration.theta).c_str());
  row("max |j|", at(r.extrema.jerk.value, "mm/rad³", r.extrema.jerk.theta).c_str());
  if (r.analysis) {
    const CamAnalysis& a = *r.analysis;
    if (r.design.follower.kind != FollowerKind::FlatFaced) {
      const double phi = a.max_pressure_angle.value * kDegreesPerRadian;
      std::snprintf(buffer, sizeof buffer, "%.2f° at %.2f° (limit %.1f°)", phi,
                    a.max_pressure_angle.theta * kDegreesPerRadian,
                    view.pressure_angle_limit * kDegreesPerRadian);
      row("max |pressure angle|", buffer, a.max_pressure_angle.value > view.pressure_angle_limit);
    }
    const auto radius = [&](const char* name, const Extremum& e) {
      if (std::isinf(e.value))
        row(name, "none");
      else
        row(name, at(e.value, "mm", e.theta).c_str());
    };
    radius("min convex radius, pitch", a.min_convex_pitch_radius);
    radius("min convex radius, contour", a.min_convex_contour_radius);
    radius("min concave radius, contour", a.min_concave_contour_radius);
    if (a.undercut.empty()) {
      row("undercut", "none");
    } else {
      std::string ranges;
      for (const AngleRange& u : a.undercut) {
        std::snprintf(buffer, sizeof buffer, "%s%.1f°–%.1f°", ranges.empty() ? "" : ", ",
                      u.from * kDegreesPerRadian, u.to * kDegreesPerRadian);
        ranges += buffer;
      }
      row("undercut", ranges.c_str(), true);
    }
    if (a.face_width) {
      std::snprintf(buffer, sizeof buffer, "%.4g mm (%.4g … %.4g)", a.face_width->width(),
                    a.face_width->left, a.face_width->right);
      row("face width needed", buffer);
    }
  }
  std::snprintf(buffer, sizeof buffer, "%zu", r.issues.size());
  row("continuity issues", buffer, !r.issues.empty());
  ImGui::EndTable();
  for (const ContinuityIssue& issue : r.issues) {
    ImGui::PushStyleColor(ImGuiCol_Text,
                          issue.derivative <= 2 ? color::error : IM_COL32(170, 110, 0, 255));
    ImGui::Bullet();
    ImGui::TextWrapped("%s", issue.message().c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace polarform::studio
