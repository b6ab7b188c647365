#include "ui/studio/segment_table.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

#include "designers/cam/motion_law.h"
#include "ui/studio/guarded.h"
#include "ui/studio/segment_edits.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr double kDefaultLift = 10.0;  // mm, for a dwell turned into a rise or return

// A table is shown but not offered: its rows come from a file the project names.
constexpr std::array<MotionLaw, 14> kLaws = {MotionLaw::Cycloidal,
                                             MotionLaw::SimpleHarmonic,
                                             MotionLaw::ModifiedSine,
                                             MotionLaw::ModifiedTrapezoid,
                                             MotionLaw::Scca,
                                             MotionLaw::Polynomial345,
                                             MotionLaw::Polynomial4567,
                                             MotionLaw::ConstantAcceleration,
                                             MotionLaw::Cubic,
                                             MotionLaw::DoubleHarmonic,
                                             MotionLaw::ConstantVelocity,
                                             MotionLaw::Polynomial,
                                             MotionLaw::BSpline,
                                             MotionLaw::Table};
constexpr std::array<SegmentKind, 4> kKinds = {SegmentKind::Dwell, SegmentKind::Rise,
                                               SegmentKind::Return, SegmentKind::RiseReturn};

template <class Enum, std::size_t N>
int index_of(const std::array<Enum, N>& values, Enum v) {
  for (std::size_t i = 0; i < N; ++i)
    if (values[i] == v) return static_cast<int>(i);
  return 0;
}

// `unit`: of s, "mm" or "°" (an oscillating follower's swing).
bool endpoint_inputs(const char* id, EndpointDerivatives& e, int order, const std::string& unit) {
  bool changed = false;
  ImGui::PushID(id);
  if (order >= 1) changed |= input_number(("velocity [" + unit + "/rad]").c_str(), e.velocity, 1.0);
  if (order >= 2)
    changed |= input_number(("acceleration [" + unit + "/rad²]").c_str(), e.acceleration, 1.0);
  if (order >= 3) changed |= input_number(("jerk [" + unit + "/rad³]").c_str(), e.jerk, 1.0);
  ImGui::PopID();
  return changed;
}

// A polynomial law's degree (0: the least the constraints determine) and its interior
// constraints S^(k)(x) = value in normalised units (constrained_polynomial.h).
bool polynomial_inputs(SegmentSpec& s) {
  bool changed = false;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
  changed |=
      input_int("polynomial degree", s.polynomial_degree, 0, kMaxConstrainedPolynomialDegree);
  help_marker(
      "0: the least degree the constraints determine. More coefficients than constraints: the "
      "polynomial of least jerk energy; fewer: an error.");
  int remove = -1;
  for (std::size_t i = 0; i < s.interior.size(); ++i) {
    PolynomialConstraint& c = s.interior[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
    changed |= input_number("x", c.x, 0.05);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
    changed |= input_int("S^(k), k", c.derivative, 0, kMaxConstraintDerivative);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 5);
    changed |= input_number("=", c.value, 0.05);
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) remove = static_cast<int>(i);
    ImGui::PopID();
  }
  if (remove >= 0) {
    s.interior.erase(s.interior.begin() + remove);
    changed = true;
  }
  if (ImGui::SmallButton("add interior constraint")) {
    s.interior.push_back({});
    changed = true;
  }
  help_marker("Normalised: x = (θ − start)/β in (0, 1), S = s/lift, S^(k) = s^(k)·β^k/lift.");
  return changed;
}

}  // namespace

bool SegmentTable::draw(std::vector<SegmentSpec>& segments, MessageLog& log,
                        std::string_view unit) {
  unit_ = unit;
  bool changed = false;
  if (segments.empty()) {
    ImGui::TextDisabled("No segments.");
    return false;
  }
  selected_ = std::clamp(selected_, 0, static_cast<int>(segments.size()) - 1);
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  if (ImGui::BeginTable("segments", 6, flags)) {
    ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("kind", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("law", ImGuiTableColumnFlags_WidthStretch, 1.6f);
    ImGui::TableSetupColumn("start [°]", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("end [°]", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn(("lift [" + unit_ + "]").c_str(), ImGuiTableColumnFlags_WidthStretch,
                            1.0f);
    ImGui::TableHeadersRow();
    for (int i = 0; i < static_cast<int>(segments.size()); ++i) changed |= draw_row(segments, i);
    ImGui::EndTable();
  }
  changed |= draw_buttons(segments, log);
  ImGui::Separator();
  changed |= draw_details(segments[selected_]);
  return changed;
}

bool SegmentTable::draw_row(std::vector<SegmentSpec>& segments, int i) {
  bool changed = false;
  SegmentSpec& s = segments[i];
  const int last = static_cast<int>(segments.size()) - 1;
  ImGui::PushID(i);
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  if (ImGui::Selectable(
          std::to_string(i + 1).c_str(), selected_ == i,
          ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap))
    selected_ = i;
  if (!s.name.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.name.c_str());

  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  int kind = index_of(kKinds, s.kind);
  static constexpr std::array<std::string_view, 4> kKindNames = {"dwell", "rise", "return",
                                                                 "rise-return"};
  if (combo("##kind", kind, kKindNames)) {
    set_kind(s, kKinds[kind], kDefaultLift);
    changed = true;
  }

  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (s.kind == SegmentKind::Dwell) {
    ImGui::TextDisabled("—");
  } else {
    std::array<std::string_view, kLaws.size()> names;
    for (std::size_t k = 0; k < kLaws.size(); ++k) names[k] = motion_law_name(kLaws[k]);
    int law = index_of(kLaws, s.law);
    if (combo("##law", law, names) && kLaws[law] != MotionLaw::Table) {
      s.law = kLaws[law];
      changed = true;
    }
  }

  // Start and end edit the shared boundaries; 0° and 360° stay fixed.
  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (i == 0) {
    ImGui::TextDisabled("%.2f", s.start * kDegreesPerRadian);
  } else {
    double start = s.start;
    if (drag_angle("##start", start, 0.0, 360.0)) {
      set_boundary(segments, i, start);
      changed = true;
    }
  }
  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (i == last) {
    ImGui::TextDisabled("%.2f", segments[i].end * kDegreesPerRadian);
  } else {
    double end = segments[i].end;
    if (drag_angle("##end", end, 0.0, 360.0)) {
      set_boundary(segments, i + 1, end);
      changed = true;
    }
  }
  ImGui::TableNextColumn();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (segments[i].kind == SegmentKind::Dwell)
    ImGui::TextDisabled("—");
  else
    changed |= drag_number("##lift", segments[i].lift, 0.05, 0.0, 1e4, "%.3f");
  ImGui::PopID();
  return changed;
}

bool SegmentTable::draw_buttons(std::vector<SegmentSpec>& segments, MessageLog& log) {
  bool changed = false;
  if (ImGui::Button("Add dwell")) {
    changed |= guarded(log, "Add dwell",
                      [&] { selected_ = insert_dwell_after(segments, selected_); });
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Split the selected segment: a new dwell takes its second half");
  ImGui::SameLine();
  ImGui::BeginDisabled(segments.size() < 2);
  if (ImGui::Button("Delete")) {
    changed |= guarded(log, "Delete segment", [&] {
      delete_segment(segments, selected_);
      selected_ = std::max(0, selected_ - 1);
    });
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(selected_ == 0);
  if (ImGui::ArrowButton("up", ImGuiDir_Up)) {
    changed |= guarded(log, "Move segment",
                      [&] { selected_ = move_segment(segments, selected_, -1); });
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(selected_ + 1 >= static_cast<int>(segments.size()));
  if (ImGui::ArrowButton("down", ImGuiDir_Down)) {
    changed |= guarded(log, "Move segment",
                      [&] { selected_ = move_segment(segments, selected_, +1); });
  }
  ImGui::EndDisabled();
  help_marker(
      "Segments cover 0°–360° in order. Editing an end angle moves the boundary it shares with the "
      "next segment; you can also drag the dashed boundaries in the motion plots. Rises and "
      "returns "
      "must cancel over the revolution.");
  return changed;
}

bool SegmentTable::draw_details(SegmentSpec& s) {
  bool changed = false;
  ImGui::Text("Segment %d", selected_ + 1);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  changed |= ImGui::InputTextWithHint("##name", "name (optional)", &s.name);
  if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::Scca) {
    // b and c are edited; d = 1 − b − c keeps the fractions a partition of the segment.
    changed |= drag_number("b (sine ramps)", s.scca.b, 0.005, 0.0, 1.0 - s.scca.c, "%.3f");
    changed |= drag_number("c (constant)", s.scca.c, 0.005, 0.0, 1.0 - s.scca.b, "%.3f");
    s.scca.d = std::max(0.0, 1.0 - s.scca.b - s.scca.c);
    ImGui::Text("d (cosine turn) = %.3f", s.scca.d);
    help_marker(
        "SCCA (Norton): b = 0.25, c = 0.5 is the modified trapezoid; b = 0.25, c = 0 the "
        "modified sine; b = 0.5, c = 0 the cycloidal; b = c = 0 the harmonic law.");
    return changed;
  }
  if (s.kind != SegmentKind::Dwell && s.law == MotionLaw::ConstantVelocity) {
    changed |= drag_number("blend (each end)", s.blend, 0.005, 0.0, 0.5, "%.3f");
    return changed;
  }
  if (s.kind == SegmentKind::Dwell ||
      (s.law != MotionLaw::Polynomial && s.law != MotionLaw::BSpline)) {
    ImGui::TextDisabled("Endpoint constraints apply to polynomial and B-spline laws.");
    return changed;
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
  changed |= input_int("constrained derivatives", s.constrained_order, 0, 3);
  help_marker(
      "Displacement is always met at both ends; derivatives 1..N (velocity, acceleration, jerk) "
      "are "
      "prescribed. 2 with zero values is Bae 2002, eq. (5.1).");
  if (s.constrained_order > 0 && ImGui::BeginTable("ends", 2, ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("at start");
    changed |= endpoint_inputs("start", s.at_start, s.constrained_order, unit_);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("at end");
    changed |= endpoint_inputs("end", s.at_end, s.constrained_order, unit_);
    ImGui::EndTable();
  }
  if (s.law == MotionLaw::Polynomial && s.kind != SegmentKind::RiseReturn)
    changed |= polynomial_inputs(s);
  if (s.law == MotionLaw::BSpline) {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
    changed |= input_int("B-spline degree", s.bspline.degree, 1, 9);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
    changed |= input_int("control values", s.bspline.control_values, 2, 64);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8);
    changed |= input_int("minimised derivative", s.bspline.minimised_derivative, 1, 9);
  }
  return changed;
}

}  // namespace polarform::studio
