#include "ui/studio/cam_workspace.h"

#include <imgui.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>

#include "jobs/cam/cam_report.h"
#include "jobs/report/report_lines.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/cam_summary_panel.h"
#include "ui/studio/colors.h"
#include "ui/studio/guarded.h"
#include "ui/studio/segment_edits.h"
#include "ui/studio/splitter.h"
#include "ui/studio/template_picker.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {

CamWorkspace::CamWorkspace(StudioContext& context) : Workspace(context) {}

bool CamWorkspace::open(const std::filesystem::path& file, bool as_template) {
  return guarded(log(), "Open " + file.filename().string(), [&] {
    std::vector<std::string> warnings;
    CamProject edit = read_cam_project(file, warnings);
    for (const auto& w : warnings) log().warning(w);
    document_.replace(std::move(edit), as_template ? std::filesystem::path() : file,
                      as_template ? file.stem().string() + " (new)" : file.filename().string());
    has_document_ = true;
    computed_.reset();
    design_.reset();
    analysis_.reset();
    conversion_.reset();
    design_error_.clear();
    conversion_error_.clear();
    segment_table_.select(0);
    log().info(as_template ? "New cam from template " + file.filename().string()
                           : "Opened " + file.string());
  });
}

bool CamWorkspace::save(const std::filesystem::path& file) {
  return guarded(log(), "Save " + file.filename().string(), [&] {
    write_cam_project(document_.current(), file);
    document_.saved_as(file);
    log().info("Saved " + file.string());
  });
}

void CamWorkspace::update() {
  if (!has_document_) return;
  if (computed_ && *computed_ == document_.current()) return;
  recompute();
}

// The stages the studio runs live: the analyses and the conversion of the CLI's job, the error
// curve at fewer samples and without the degree-limited extra (the export runs the whole job).
CamJobOptions CamWorkspace::live_options() {
  CamJobOptions options;
  options.error_samples = 720;
  options.with_limited = false;
  return options;
}

void CamWorkspace::recompute() {
  const auto start = std::chrono::steady_clock::now();
  const CamProject& current = document_.current();
  // Messages go to the log once an edit has settled, not for every frame of a drag.
  const bool settled = !ImGui::IsAnyItemActive();
  const auto report = [&](const std::string& what, std::string& last) {
    const std::string message = failure_text(what, std::current_exception());
    if (settled && message != last) log().error(message);
    last = message;
  };
  const bool design_changed = !computed_ || !(computed_->cam == current.cam);
  try {
    CamDesignStage design = design_cam(current);
    if (design_changed || !analysis_) analysis_ = analyse_cam(design, live_options());
    design_ = std::move(design);
    design_error_.clear();
    design_stale_ = false;
  } catch (...) {
    report("Cam design", design_error_);
    design_stale_ = true;
  }
  if (!design_stale_) {
    try {
      conversion_ = convert_cam(*design_, live_options());
      conversion_error_.clear();
      conversion_stale_ = false;
    } catch (...) {
      report("NURBS conversion", conversion_error_);
      conversion_stale_ = true;
    }
  } else {
    conversion_stale_ = true;
  }
  ++revision_;
  computed_ = current;
  compute_ms_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void CamWorkspace::draw() {
  if (!has_document_) {
    if (const auto chosen =
            draw_template_picker("Start a cam from a template:", context_.examples / "cams"))
      open(*chosen, true);
    return;
  }
  if (view_.animate) {
    const double dt = ImGui::GetIO().DeltaTime;
    view_.follower_angle =
        std::fmod(view_.follower_angle + dt * 2 * std::numbers::pi / view_.animation_period,
                  2 * std::numbers::pi);
  }
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float min_width = ImGui::GetFontSize() * 14;
  float& left_fraction = layout("cam.left", 0.3f);
  const float left = split_size(left_fraction, avail.x, min_width);
  ImGui::BeginChild("cam editor", ImVec2(left, avail.y), true);
  draw_editor();
  ImGui::EndChild();
  ImGui::SameLine(0, 0);
  vertical_splitter("cam split left", left_fraction, avail.x);
  ImGui::SameLine(0, 0);
  ImGui::BeginChild("cam results", ImVec2(0, avail.y), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  draw_banner();
  if (design_ && analysis_) {
    const ImVec2 rest = ImGui::GetContentRegionAvail();
    float& middle_fraction = layout("cam.middle", 0.45f);
    const float middle = split_size(middle_fraction, rest.x, min_width);
    ImGui::BeginChild("svaj", ImVec2(middle, rest.y), false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    draw_plots();
    ImGui::EndChild();
    ImGui::SameLine(0, 0);
    vertical_splitter("cam split right", middle_fraction, rest.x);
    ImGui::SameLine(0, 0);
    ImGui::BeginChild("profile and conversion", ImVec2(0, rest.y), false,
                      ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    draw_profile_and_conversion();
    ImGui::EndChild();
  }
  ImGui::EndChild();
  document_.settle(ImGui::IsAnyItemActive());
}

void CamWorkspace::draw_banner() {
  if (design_error_.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, color::error);
  ImGui::TextWrapped("%s", design_error_.c_str());
  ImGui::PopStyleColor();
  ImGui::TextDisabled(
      design_ ? "The plots show the last valid design; undo (Ctrl+Z) or fix the value above."
              : "Fix the design on the left, or undo (Ctrl+Z).");
}

void CamWorkspace::draw_editor() {
  CamProject& edit = document_.edit();
  if (ImGui::CollapsingHeader("Segments", ImGuiTreeNodeFlags_DefaultOpen))
    segment_table_.draw(edit.cam.segments, log(), motion_unit_symbol(edit.cam.follower.kind));
  if (ImGui::CollapsingHeader("Follower and cam", ImGuiTreeNodeFlags_DefaultOpen)) {
    settings_panel_.draw(edit.cam, view_, log());
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9);
    // The limit is the project's (the CLI's report uses the same); the view only mirrors it.
    double limit = edit.pressure_angle_limit.value_or(
        default_pressure_angle_limit(edit.cam).value_or(view_.pressure_angle_limit));
    if (drag_angle("pressure-angle limit", limit, 1.0, 89.0)) edit.pressure_angle_limit = limit;
    view_.pressure_angle_limit = limit;
    static constexpr std::string_view kUnits[] = {"per radian", "in time at the speed"};
    int units = view_.units == MotionUnits::per_radian ? 0 : 1;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9);
    if (combo("motion units", units, kUnits))
      view_.units = units == 0 ? MotionUnits::per_radian : MotionUnits::time;
  }
  if (ImGui::CollapsingHeader("NURBS conversion", ImGuiTreeNodeFlags_DefaultOpen)) {
    conversion_panel_.draw_settings(edit.conversion);
    bool capped = edit.max_degree.has_value();
    if (ImGui::Checkbox("cap the exported degree", &capped))
      edit.max_degree = capped ? std::optional<int>(3) : std::nullopt;
    if (edit.max_degree) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
      int degree = *edit.max_degree;
      if (input_int("max degree", degree, 1, 25)) edit.max_degree = degree;
    }
    help_marker(
        "Profile files of a higher exact degree are then approximated at this degree within the "
        "tolerance "
        "and the measured error is reported (DESIGN §4.6).");
    conversion_panel_.draw_result(
        conversion_ ? &conversion_->conversion : nullptr, conversion_ ? conversion_->degree() : 0,
        conversion_ ? conversion_->control_points() : 0, conversion_error_, conversion_stale_);
  }
  if (design_ && analysis_ && ImGui::CollapsingHeader("Analysis", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (design_stale_) ImGui::TextDisabled("(last valid design)");
    draw_cam_summary(*design_, *analysis_, view_);
  }
  if (ImGui::CollapsingHeader("Dynamics")) {
    if (edit.cam.type == CamType::Plate) draw_dynamics_settings(edit.load, edit.cam.follower.kind);
    if (design_ && analysis_) draw_dynamics_summary(*design_, *analysis_);
  }
  ImGui::TextDisabled("recomputed in %.2f ms", compute_ms_);
}

// The motion (SVAJ) plots, and beside them in a tab the dynamics' when the project has them.
void CamWorkspace::draw_plots() {
  std::vector<SegmentSpec>& segments = document_.edit().cam.segments;
  if (!analysis_->dynamics) {
    svaj_.draw(*design_, *analysis_, revision_, view_, segments, ImGui::GetContentRegionAvail());
    return;
  }
  if (!ImGui::BeginTabBar("plots")) return;
  if (ImGui::BeginTabItem("Motion")) {
    svaj_.draw(*design_, *analysis_, revision_, view_, segments, ImGui::GetContentRegionAvail());
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Dynamics")) {
    dynamics_.draw(*design_, *analysis_, revision_, ImGui::GetContentRegionAvail());
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

void CamWorkspace::draw_profile_and_conversion() {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float& fraction = layout("cam.profile", 0.62f);
  const float top = split_size(fraction, avail.y, ImGui::GetFontSize() * 8);
  ImGui::BeginChild("profile", ImVec2(0, top), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  const PlateProfile* plate = conversion_ && !conversion_stale_
                                  ? std::get_if<PlateProfile>(&conversion_->profile)
                                  : nullptr;
  profile_.draw(*design_, *analysis_, plate ? &plate->curve : nullptr, view_);
  ImGui::EndChild();
  horizontal_splitter("profile split", fraction, avail.y);
  ImGui::BeginChild("conversion error", ImVec2(0, 0), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  if (conversion_)
    conversion_panel_.draw_error_plot(*conversion_, revision_, ImGui::GetContentRegionAvail());
  else
    ImGui::TextDisabled("No conversion: %s", conversion_error_.c_str());
  ImGui::EndChild();
}

void CamWorkspace::bench_step(int frame, int frames) {
  // Scripted edit: the boundary after the first segment dragged back over half of that segment,
  // one step per frame (each frame recomputes the analyses and the conversion).
  std::vector<SegmentSpec>& segments = document_.edit().cam.segments;
  if (segments.size() < 2) return;
  if (frame == 0) bench_boundary_ = segments[1].start;
  const double width = bench_boundary_ - segments[0].start;
  const double t = static_cast<double>(frame + 1) / frames;
  set_boundary(segments, 1, bench_boundary_ - 0.5 * width * std::sin(0.5 * std::numbers::pi * t));
}

std::string CamWorkspace::numbers() const {
  std::ostringstream out;
  const CamProject& edit = document_.current();
  out << "segments=" << edit.cam.segments.size()
      << "\nvalid=" << (design_error_.empty() && design_ ? 1 : 0) << "\n";
  for (std::size_t k = 1; k < edit.cam.segments.size(); ++k)
    out << "boundary_" << k
        << "_deg=" << format_round_trip(edit.cam.segments[k].start * kDegreesPerRadian) << "\n";
  if (design_ && analysis_ && design_error_.empty()) {
    out << "stroke_mm=" << format_round_trip(design_->program.stroke()) << "\n";
    // The fields of report.json for the stages shown, from the job's own report builder.
    out << report_lines(cam_report_fields(
        *design_, *analysis_, conversion_ && !conversion_stale_ ? &*conversion_ : nullptr));
  }
  out << "compute_ms=" << compute_ms_ << "\n";
  return out.str();
}

}  // namespace polarform::studio
