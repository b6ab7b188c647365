#include "ui/studio/cam_summary_panel.h"

#include <imgui.h>

#include <cmath>

#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

void row(const char* name, const std::string& value, bool bad = false) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  if (bad) ImGui::PushStyleColor(ImGuiCol_Text, color::error);
  ImGui::TextUnformatted(value.c_str());
  if (bad) ImGui::PopStyleColor();
}

std::string at(const Extremum& e, const char* unit) {
  return number_text(e.value) + " " + unit + " at " + degrees_text(e.theta);
}

}  // namespace

void draw_cam_summary(const CamDesignStage& d, const CamAnalysisStage& s,
                      const CamViewSettings& view) {
  if (!ImGui::BeginTable("summary", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  const std::string u(motion_unit_symbol(d.project.cam.follower.kind));
  row(is_oscillating(d.project.cam.follower.kind) ? "arm swing" : "stroke",
      number_text(d.program.stroke()) + (u == "°" ? u : " " + u));
  const MotionExtrema& m = s.motion_extrema();
  row("max |v|", at(m.velocity, (u + "/rad").c_str()));
  row("max |a|", at(m.acceleration, (u + "/rad²").c_str()));
  row("max |j|", at(m.jerk, (u + "/rad³").c_str()));
  if (const auto* plate = std::get_if<PlateCamAnalysis>(&s.cam)) {
    const CamAnalysis& a = plate->analysis;
    if (d.project.cam.follower.kind != FollowerKind::FlatFaced)
      row("max |pressure angle|",
          degrees_text(a.max_pressure_angle.value) + " at " +
              degrees_text(a.max_pressure_angle.theta) + " (limit " +
              degrees_text(view.pressure_angle_limit) + ")",
          a.max_pressure_angle.value > view.pressure_angle_limit);
    const auto radius = [&](const char* name, const Extremum& e) {
      row(name, std::isinf(e.value) ? "none" : at(e, "mm"));
    };
    radius("min convex radius, pitch", a.min_convex_pitch_radius);
    radius("min convex radius, contour", a.min_convex_contour_radius);
    radius("min concave radius, contour", a.min_concave_contour_radius);
    if (a.undercut.empty()) {
      row("undercut", "none");
    } else {
      std::string ranges;
      for (const AngleRange& u : a.undercut)
        ranges += (ranges.empty() ? "" : ", ") + degrees_text(u.from) + "–" + degrees_text(u.to);
      row("undercut", ranges, true);
    }
    if (a.face_width)
      row("face width needed", number_text(a.face_width->width()) + " mm (" +
                                   number_text(a.face_width->left) + " … " +
                                   number_text(a.face_width->right) + ")");
  } else {
    const Extremum p = s.max_pressure_angle();
    row("max |pressure angle| at the pitch radius",
        degrees_text(p.value) + " at " + degrees_text(p.theta));
  }
  row("continuity issues", std::to_string(d.continuity.size()), !d.continuity.empty());
  ImGui::EndTable();
  for (const ContinuityIssue& issue : d.continuity) {
    ImGui::PushStyleColor(ImGuiCol_Text,
                          issue.derivative <= 2 ? color::error : IM_COL32(170, 110, 0, 255));
    ImGui::Bullet();
    ImGui::TextWrapped("%s", issue.message().c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace polarform::studio
