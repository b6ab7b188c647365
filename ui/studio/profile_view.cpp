#include "ui/studio/profile_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/opaque_fill.h"
#include "ui/studio/polyline_simplify.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLegendSteps = 32;  // shades of the pressure-angle colour

Eigen::Vector2d rotated(const Eigen::Vector2d& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

// The screen points, reduced to where the line bends by more than polyline_simplify's tolerance
// (a fraction of a pixel): the same picture with fewer triangles.
std::vector<ImVec2> simplified(const Polyline& points) {
  std::vector<ImVec2> line;
  for (const PixelPoint& q : simplify_polyline(points))
    line.emplace_back(static_cast<float>(q.x), static_cast<float>(q.y));
  return line;
}

}  // namespace

void ProfileView::draw(const CamDesignStage& d, const CamAnalysisStage& a,
                       const NurbsCurve2d* converted, CamViewSettings& view) {
  const PlateCam* plate = std::get_if<PlateCam>(&d.cam);
  draw_toolbar(view, plate != nullptr);
  const ImVec2 min = ImGui::GetCursorScreenPos();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 canvas(std::max(avail.x, 100.0f), std::max(avail.y, 100.0f));
  ImGui::InvisibleButton("profile", canvas);
  view2d_.handle_input(ImGui::IsItemHovered(), ImGui::IsItemActive());
  const ImVec2 max(min.x + canvas.x, min.y + canvas.y);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  add_opaque_rect(dl, min, max, color::background);
  dl->PushClipRect(min, max, true);
  if (plate)
    draw_plate(*plate, a, converted, view, min, max);
  else
    draw_barrel(std::get<BarrelCam>(d.cam), a, view, min, max);
  dl->PopClipRect();
  dl->AddRect(min, max, color::frame);
}

void ProfileView::draw_toolbar(CamViewSettings& view, bool plate) {
  if (plate) {
    ImGui::Checkbox("pitch curve", &view.show_pitch);
    ImGui::SameLine();
    ImGui::Checkbox("base circle", &view.show_base_circle);
    ImGui::SameLine();
    ImGui::Checkbox("control polygon", &view.show_control_polygon);
    ImGui::SameLine();
    ImGui::Checkbox("curvature comb", &view.show_curvature_comb);
    ImGui::Checkbox("pressure-angle colour", &view.show_pressure_colour);
    ImGui::SameLine();
    ImGui::Checkbox("follower", &view.show_follower);
    ImGui::SameLine();
    ImGui::Checkbox("cam turns", &view.cam_turns);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("On: fixed frame, the cam turns under the follower.\nOff: cam frame.");
  }
  ImGui::Checkbox("animate", &view.animate);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7);
  double angle = view.follower_angle;
  if (drag_angle("cam angle θ", angle, 0.0, 360.0)) view.follower_angle = angle;
  if (plate && view.show_curvature_comb) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
    log_slider("comb scale", view.comb_scale, 0.01, 10.0, "%.2f");
  }
}

void ProfileView::draw_plate(const PlateCam& cam, const CamAnalysisStage& a,
                             const NurbsCurve2d* converted, const CamViewSettings& view, ImVec2 min,
                             ImVec2 max) {
  const PlateCamAnalysis& plate = std::get<PlateCamAnalysis>(a.cam);
  const PlateCurves& p = plate.curves;
  const std::vector<double>& pressure = a.curves.pressure_angle;
  rotation_ = view.cam_turns ? cam.sense() * view.follower_angle : 0.0;
  double extent = cam.base_radius();
  for (const auto& q : p.pitch) extent = std::max(extent, q.norm());
  const double roller = has_roller(cam.follower().kind) ? cam.follower().roller_radius : 0.0;
  extent += roller;
  if (is_oscillating(cam.follower().kind)) extent = std::max(extent, 1.1 * cam.pivot().norm());
  view2d_.set_canvas(min, max, Box2{-extent, -extent, extent, extent * 1.35});
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const auto screen = [&](const Eigen::Vector2d& q) {
    const Eigen::Vector2d v = rotated(q, rotation_);
    return view2d_.to_screen(v.x(), v.y());
  };
  const ImVec2 centre = view2d_.to_screen(0, 0);
  const float scale = static_cast<float>(view2d_.pixels_per_unit());
  if (view.show_base_circle) {  // 0 segments: ImGui picks enough for a 0.3 px error
    dl->AddCircle(centre, static_cast<float>(cam.base_radius()) * scale, color::muted, 0, 1.0f);
    if (roller > 0)
      dl->AddCircle(centre, static_cast<float>(cam.prime_radius()) * scale, color::grid, 0, 1.0f);
  }
  dl->AddLine(ImVec2(centre.x - 6, centre.y), ImVec2(centre.x + 6, centre.y), color::frame);
  dl->AddLine(ImVec2(centre.x, centre.y - 6), ImVec2(centre.x, centre.y + 6), color::frame);

  std::vector<ImVec2> line;
  if (view.show_pitch && roller > 0) {
    Polyline pitch;
    for (const auto& q : p.pitch) pitch.push_back({screen(q).x, screen(q).y});
    line = simplified(pitch);
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), palette_color(0, 0.55f),
                    ImDrawFlags_Closed, 1.0f);
  }
  if (view.show_curvature_comb) {
    const double length = view.comb_scale * cam.base_radius() * cam.base_radius();
    line.clear();
    for (std::size_t i = 0; i < p.contour.size(); i += 2) {
      const Eigen::Vector2d tip = p.contour[i] + p.normal[i] * (p.curvature[i] * length);
      dl->AddLine(screen(p.contour[i]), screen(tip), palette_color(3, 0.45f));
      line.push_back(screen(tip));
    }
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), palette_color(3, 0.9f), 0, 1.0f);
  }
  // The contour in runs of one colour: the pressure angle in the legend's kLegendSteps shades.
  const double limit = std::max(view.pressure_angle_limit, 1e-6);
  const bool coloured = view.show_pressure_colour && cam.follower().kind != FollowerKind::FlatFaced;
  const auto shade = [&](std::size_t i) {
    if (!coloured) return color::text;
    const double t = std::abs(pressure[i]) / limit;
    return t > 1.0 ? color::error
                   : sequential_color((std::floor(t * kLegendSteps) + 0.5) / kLegendSteps);
  };
  for (std::size_t begin = 0; begin + 1 < p.contour.size();) {
    const ImU32 c = shade(begin);
    std::size_t end = begin + 1;
    while (end + 1 < p.contour.size() && shade(end) == c) ++end;
    Polyline run;
    for (std::size_t i = begin; i <= end; ++i) {
      const ImVec2 q = screen(p.contour[i]);
      run.push_back({q.x, q.y});
    }
    line = simplified(run);
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), c, 0, 3.0f);
    begin = end;
  }
  if (converted && view.show_control_polygon) {
    line.clear();
    for (const auto& q : converted->control_points()) line.push_back(screen(q));
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), palette_color(1, 0.8f), 0, 1.0f);
    for (const ImVec2& q : line)
      dl->AddRectFilled(ImVec2(q.x - 2, q.y - 2), ImVec2(q.x + 2, q.y + 2), palette_color(1));
  }
  if (view.show_follower) draw_follower(cam, plate.analysis, view, dl);
  if (view.show_pressure_colour && cam.follower().kind != FollowerKind::FlatFaced)
    draw_legend(view, min, dl);
  if (ImGui::IsItemHovered()) hover_readout(cam, a, view);
}

void ProfileView::draw_follower(const PlateCam& cam, const CamAnalysis& analysis,
                                const CamViewSettings& view, ImDrawList* dl) const {
  const double theta = view.follower_angle;
  Eigen::Vector2d pitch[1], contact[1];
  cam.pitch(theta, 0, pitch);
  cam.contour(theta, 0, contact);
  // The follower axis is +y in the fixed frame; in the cam frame it is turned back by σθ.
  const double back = -cam.sense() * theta;
  const Eigen::Vector2d dir = rotated(rotated(Eigen::Vector2d(0, 1), back), rotation_);
  const Eigen::Vector2d side(dir.y(), -dir.x());
  const Eigen::Vector2d P = rotated(pitch[0], rotation_), C = rotated(contact[0], rotation_);
  const auto at = [&](const Eigen::Vector2d& q) { return view2d_.to_screen(q.x(), q.y()); };
  const double rb = cam.base_radius();
  const ImU32 body = IM_COL32(70, 70, 80, 255), fill = IM_COL32(200, 205, 215, 200);
  const float scale = static_cast<float>(view2d_.pixels_per_unit());
  switch (cam.follower().kind) {
    case FollowerKind::Roller: {
      const double rr = cam.follower().roller_radius;
      const Eigen::Vector2d a = P + side * (0.3 * rr), b = P - side * (0.3 * rr);
      const Eigen::Vector2d top = dir * (0.9 * rb);
      dl->AddQuadFilled(at(a), at(a + top), at(b + top), at(b), fill);
      dl->AddCircleFilled(at(P), static_cast<float>(rr) * scale, fill, 64);
      dl->AddCircle(at(P), static_cast<float>(rr) * scale, body, 64, 1.5f);
      dl->AddCircleFilled(at(P), 2.5f, body);
      break;
    }
    case FollowerKind::KnifeEdge: {
      const double h = 0.25 * rb;
      dl->AddTriangleFilled(at(C), at(C + dir * h + side * (0.08 * rb)),
                            at(C + dir * h - side * (0.08 * rb)), fill);
      dl->AddTriangle(at(C), at(C + dir * h + side * (0.08 * rb)),
                      at(C + dir * h - side * (0.08 * rb)), body, 1.5f);
      dl->AddLine(at(C + dir * h), at(C + dir * (h + 0.8 * rb)), body, 3.0f);
      break;
    }
    case FollowerKind::OscillatingRoller:
    case FollowerKind::OscillatingFlatFaced:
      draw_arm(cam, analysis, back, P, C, dl);
      break;
    case FollowerKind::FlatFaced: {
      double left = -0.5 * rb, right = 0.5 * rb;
      if (analysis.face_width) {
        left = std::min(left, analysis.face_width->left * 1.1);
        right = std::max(right, analysis.face_width->right * 1.1);
      }
      const Eigen::Vector2d a = P - side * left, b = P - side * right;  // side points to -x
      dl->AddQuadFilled(at(a), at(a + dir * (0.06 * rb)), at(b + dir * (0.06 * rb)), at(b), fill);
      dl->AddLine(at(a), at(b), body, 2.0f);
      dl->AddLine(at(P), at(P + dir * (0.9 * rb)), body, 3.0f);
      break;
    }
  }
  dl->AddCircleFilled(at(C), 3.5f, color::error);
}

// The swing arm in the cam frame (the pivot turned back by σθ with the world): a grounded pivot,
// the arm to the roller centre P with the roller, or to the face's foot and the face through the
// contact C, as long as the face width the analysis asks for.
void ProfileView::draw_arm(const PlateCam& cam, const CamAnalysis& analysis, double back,
                           const Eigen::Vector2d& P, const Eigen::Vector2d& C,
                           ImDrawList* dl) const {
  const auto at = [&](const Eigen::Vector2d& q) { return view2d_.to_screen(q.x(), q.y()); };
  const ImU32 body = IM_COL32(70, 70, 80, 255), fill = IM_COL32(200, 205, 215, 200);
  const float scale = static_cast<float>(view2d_.pixels_per_unit());
  const Eigen::Vector2d pivot = rotated(rotated(cam.pivot(), back), rotation_);
  if (cam.follower().kind == FollowerKind::OscillatingRoller) {
    const double rr = cam.follower().roller_radius;
    dl->AddLine(at(pivot), at(P), body, 4.0f);
    dl->AddCircleFilled(at(P), static_cast<float>(rr) * scale, fill, 64);
    dl->AddCircle(at(P), static_cast<float>(rr) * scale, body, 64, 1.5f);
    dl->AddCircleFilled(at(P), 2.5f, body);
  } else {
    // The reference point is the foot h n of the face from the cam centre: n = P/|P|.
    const Eigen::Vector2d n = P.normalized(), foot = pivot - cam.follower().face_offset * n;
    const Eigen::Vector2d along = (C - foot).norm() > 0 ? Eigen::Vector2d((C - foot).normalized())
                                                        : Eigen::Vector2d(-n.y(), n.x());
    const double reach = std::max((C - foot).norm() + 0.15 * cam.base_radius(),
                                  analysis.face_width ? 1.1 * analysis.face_width->right : 0.0);
    dl->AddLine(at(pivot), at(foot), body, 4.0f);
    dl->AddLine(at(foot), at(foot + along * reach), body, 3.0f);
  }
  const float r = 5.0f;  // the grounded pivot
  const ImVec2 q = at(pivot);
  dl->AddTriangleFilled(q, ImVec2(q.x - 2 * r, q.y + 3 * r), ImVec2(q.x + 2 * r, q.y + 3 * r),
                        fill);
  dl->AddCircleFilled(q, r, body);
}

void ProfileView::draw_legend(const CamViewSettings& view, ImVec2 min, ImDrawList* dl) const {
  const float fh = ImGui::GetFontSize();
  const ImVec2 o(min.x + fh * 0.6f, min.y + fh * 0.6f);
  const float w = fh * 8, h = fh * 0.6f;
  const int steps = kLegendSteps;
  for (int i = 0; i < steps; ++i) {
    const float x0 = o.x + w * i / steps, x1 = o.x + w * (i + 1) / steps;
    dl->AddRectFilled(ImVec2(x0, o.y), ImVec2(x1, o.y + h), sequential_color((i + 0.5) / steps));
  }
  dl->AddRectFilled(ImVec2(o.x + w, o.y), ImVec2(o.x + w + fh, o.y + h), color::error);
  const std::string text = "|pressure angle|: 0 … " +
                           number_text(view.pressure_angle_limit * kDegreesPerRadian) +
                           "°, red above";
  dl->AddText(ImVec2(o.x, o.y + h + 2), color::text, text.c_str());
}

void ProfileView::hover_readout(const PlateCam& cam, const CamAnalysisStage& a,
                                const CamViewSettings& view) const {
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const PlateCurves& p = std::get<PlateCamAnalysis>(a.cam).curves;
  std::size_t best = p.contour.size();
  float best_d = ImGui::GetFontSize();
  for (std::size_t i = 0; i < p.contour.size(); ++i) {
    const Eigen::Vector2d q = rotated(p.contour[i], rotation_);
    const ImVec2 s = view2d_.to_screen(q.x(), q.y());
    const float d = std::hypot(s.x - mouse.x, s.y - mouse.y);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  if (best == p.contour.size()) {
    ImGui::SetTooltip("wheel: zoom · drag: pan · double-click: fit");
    return;
  }
  const double k = p.curvature[best];
  ImGui::BeginTooltip();
  ImGui::Text("cam angle θ = %.2f°", a.curves.theta[best] * kDegreesPerRadian);
  ImGui::Text("radius R = %.4f mm", p.contour[best].norm());
  if (cam.follower().kind != FollowerKind::FlatFaced)
    ImGui::Text("pressure angle = %.2f° (limit %.1f°)",
                a.curves.pressure_angle[best] * kDegreesPerRadian,
                view.pressure_angle_limit * kDegreesPerRadian);
  if (k != 0.0)
    ImGui::Text("radius of curvature = %.4g mm (%s)", 1.0 / std::abs(k),
                k > 0 ? "convex" : "concave");
  else
    ImGui::TextUnformatted("inflection (straight)");
  ImGui::EndTooltip();
}

void ProfileView::draw_barrel(const BarrelCam& cam, const CamAnalysisStage& a,
                              const CamViewSettings& view, ImVec2 min, ImVec2 max) {
  const double rc = cam.pitch_radius(), rr = cam.roller_radius();
  const MotionCurves& m = a.curves;
  double lo = 1e300, hi = -1e300;
  for (double s : m.s) {
    lo = std::min(lo, cam.z0() + s);
    hi = std::max(hi, cam.z0() + s);
  }
  view2d_.set_canvas(min, max, Box2{0, lo - 2 * rr, 2 * kPi * rc, hi + 2 * rr});
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const auto at = [&](double x, double z) { return view2d_.to_screen(x, z); };
  std::vector<ImVec2> centre;
  for (std::size_t i = 0; i < m.theta.size(); ++i)
    centre.push_back(at(rc * m.theta[i], cam.z0() + m.s[i]));
  dl->AddPolyline(centre.data(), static_cast<int>(centre.size()), palette_color(0, 0.6f), 0, 1.0f);
  // The groove walls at the pitch radius, developed onto the pitch cylinder (x = Rc · cam angle).
  for (const auto& developed : std::get<CylindricalCamAnalysis>(a.cam).developed_walls) {
    std::vector<ImVec2> wall;
    for (const Eigen::Vector2d& w : developed) wall.push_back(at(w.x(), w.y()));
    dl->AddPolyline(wall.data(), static_cast<int>(wall.size()), color::text, 0, 2.0f);
  }
  const double theta = view.follower_angle;
  const ImVec2 roller = at(rc * theta, cam.z0() + cam.program()(theta));
  dl->AddCircleFilled(roller, static_cast<float>(rr * view2d_.pixels_per_unit()),
                      IM_COL32(200, 205, 215, 200), 48);
  dl->AddCircle(roller, static_cast<float>(rr * view2d_.pixels_per_unit()),
                IM_COL32(70, 70, 80, 255), 48, 1.5f);
  dl->AddText(ImVec2(min.x + 8, min.y + 6), color::muted,
              "developed pitch cylinder: x = Rc·θ [mm], z [mm]");
}

}  // namespace polarform::studio
