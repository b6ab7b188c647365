#include "ui/studio/cam_settings_panel.h"

#include <imgui.h>

#include <array>
#include <string>
#include <string_view>

#include "designers/cam/base_radius.h"
#include "designers/cam/cam_analysis.h"
#include "src/number_text.h"
#include "ui/studio/cam_view_settings.h"
#include "ui/studio/guarded.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr std::array<std::string_view, 2> kTypes = {"plate", "cylindrical"};
// In FollowerKind's order.
constexpr std::array<std::string_view, 5> kFollowers = {
    "knife-edge", "roller", "flat-faced", "oscillating roller", "oscillating flat-faced"};
constexpr std::array<std::string_view, 2> kPivotSides = {"right (+x)", "left (-x)"};
constexpr std::array<std::string_view, 2> kRotations = {"counter-clockwise", "clockwise"};

}  // namespace

bool CamSettingsPanel::draw(CamDesign& d, CamViewSettings& view, MessageLog& log) {
  bool changed = false;
  const float width = ImGui::GetFontSize() * 9;
  ImGui::PushItemWidth(width);
  int type = d.type == CamType::Plate ? 0 : 1;
  if (combo("cam type", type, kTypes)) {
    d.type = type == 0 ? CamType::Plate : CamType::Cylindrical;
    if (d.type == CamType::Cylindrical) {
      d.follower.kind = FollowerKind::Roller;
      if (!(d.cylinder_radius > 0)) d.cylinder_radius = d.base_radius;
      if (!(d.follower.roller_radius > 0)) d.follower.roller_radius = 0.2 * d.cylinder_radius;
    }
    changed = true;
  }
  int rotation = d.rotation == Rotation::CounterClockwise ? 0 : 1;
  if (combo("rotation", rotation, kRotations)) {
    d.rotation = rotation == 0 ? Rotation::CounterClockwise : Rotation::Clockwise;
    changed = true;
  }
  changed |= drag_number("speed [rpm]", d.rpm, 1.0, 0.001, 1e6, "%.1f");

  section("Follower");
  if (d.type == CamType::Plate) {
    int kind = static_cast<int>(d.follower.kind);
    if (combo("kind", kind, kFollowers)) {
      d.follower.kind = static_cast<FollowerKind>(kind);
      if (has_roller(d.follower.kind) && !(d.follower.roller_radius > 0))
        d.follower.roller_radius = 0.25 * d.base_radius;
      if (is_oscillating(d.follower.kind) && !(d.follower.pivot_distance > 0)) {
        // An arm that reaches the prime circle comfortably (plate_cam.h): d = 1.6 Rp, L = 1.2 Rp.
        const double rp =
            d.base_radius + (has_roller(d.follower.kind) ? d.follower.roller_radius : 0.0);
        d.follower.pivot_distance = 1.6 * rp;
        d.follower.arm_length = 1.2 * rp;
      }
      changed = true;
    }
  } else {
    ImGui::TextDisabled("roller (cylindrical cams)");
  }
  if (has_roller(d.follower.kind))
    changed |= drag_number("roller radius [mm]", d.follower.roller_radius, 0.05, 0.0, 1e5, "%.3f");
  if (d.type == CamType::Plate &&
      (d.follower.kind == FollowerKind::KnifeEdge || d.follower.kind == FollowerKind::Roller))
    changed |= drag_number("offset e [mm]", d.follower.offset, 0.05, -1e5, 1e5, "%.3f");
  if (d.type == CamType::Plate && is_oscillating(d.follower.kind)) {
    changed |=
        drag_number("pivot distance [mm]", d.follower.pivot_distance, 0.05, 0.0, 1e5, "%.3f");
    if (d.follower.kind == FollowerKind::OscillatingRoller)
      changed |= drag_number("arm length [mm]", d.follower.arm_length, 0.05, 0.0, 1e5, "%.3f");
    else
      changed |= drag_number("face offset [mm]", d.follower.face_offset, 0.05, -1e5, 1e5, "%.3f");
    int side = d.follower.pivot_side > 0 ? 0 : 1;
    if (combo("pivot side", side, kPivotSides)) {
      d.follower.pivot_side = side == 0 ? 1 : -1;
      changed = true;
    }
    ImGui::TextDisabled("segment lifts are the arm's swing in degrees");
  }

  section("Cam");
  if (d.type == CamType::Plate) {
    changed |= drag_number("base radius Rb [mm]", d.base_radius, 0.05, 0.0, 1e5, "%.3f");
    changed |= draw_base_radius_search(d, view, log);
  } else {
    changed |= drag_number("pitch radius Rc [mm]", d.cylinder_radius, 0.05, 0.0, 1e5, "%.3f");
    changed |= drag_number("track height z0 [mm]", d.z0, 0.05, -1e5, 1e5, "%.3f");
  }
  ImGui::PopItemWidth();
  return changed;
}

bool CamSettingsPanel::draw_base_radius_search(CamDesign& d, const CamViewSettings& view,
                                               MessageLog& log) {
  if (!ImGui::Button("Smallest base radius")) {
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "The smallest Rb that keeps the pressure angle within %.1f° with no undercut",
          view.pressure_angle_limit * kDegreesPerRadian);
    return false;
  }
  bool changed = false;
  guarded(log, "Smallest base radius", [&] {
    BaseRadiusRequirements req;
    req.max_pressure_angle = view.pressure_angle_limit;
    const BaseRadiusResult r =
        minimum_base_radius(make_program(d), d.follower, d.rotation, req, uniform_angles(720));
    d.base_radius = r.base_radius;
    changed = true;
    log.info("Base radius set to " + number_text(r.base_radius) + " mm (max pressure angle " +
             degrees_text(r.max_pressure_angle.value) + ")");
  });
  return changed;
}

}  // namespace polarform::studio
