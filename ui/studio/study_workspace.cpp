#include "ui/studio/study_workspace.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "designers/convert/occt_peer.h"
#include "designers/convert/sisl_peer.h"
#include "jobs/study/study_plots.h"
#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/guarded.h"
#include "ui/studio/splitter.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {

StudyWorkspace::StudyWorkspace(StudioContext& context, const CamWorkspace& cam)
    : Workspace(context), cam_(cam) {}

void StudyWorkspace::start() {
  if (!cam_.has_document()) return;
  input_ = cam_.current();
  error_.clear();
  const std::vector<double> tolerances =
      log_tolerances(settings_.loosest, settings_.tightest, settings_.per_decade);
  task_.start([project = *input_, tolerances,
               options = StudyOptions{settings_.peers}](TaskControl& control) {
    return run_study_job(
        project, tolerances, [&control](double f) { control.report(f); }, options);
  });
}

void StudyWorkspace::update() {
  if (auto outcome = task_.poll()) {
    if (outcome->value) {
      result_ = std::move(*outcome->value);
      result_input_ = input_;
      figures_.reset();
      log().info("Study: " + std::to_string(result_->rows.size()) + " tolerances in " +
                 number_text(outcome->seconds) + " s");
    } else if (outcome->error) {
      error_ = failure_text("Study", outcome->error);
      log().error(error_);
    } else {
      log().info("Study cancelled");
    }
  }
}

void StudyWorkspace::draw() {
  if (!cam_.has_document()) {
    ImGui::TextDisabled(
        "Open or create a cam design in the Cam workspace; the study sweeps its conversion.");
    return;
  }
  if (!requested_) {
    requested_ = true;
    start();
  }
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float& left_fraction = layout("study.left", 0.3f);
  const float left = split_size(left_fraction, avail.x, ImGui::GetFontSize() * 14);
  ImGui::BeginChild("study controls", ImVec2(left, avail.y), true);
  draw_controls();
  draw_table();
  draw_peer_table();
  ImGui::EndChild();
  ImGui::SameLine(0, 0);
  vertical_splitter("study split", left_fraction, avail.x);
  ImGui::SameLine(0, 0);
  ImGui::BeginChild("study plots", ImVec2(0, avail.y), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  draw_plots(ImGui::GetContentRegionAvail());
  ImGui::EndChild();
}

void StudyWorkspace::draw_controls() {
  section("Tolerance sweep");
  ImGui::TextWrapped("Design: %s", cam_.document_name().c_str());
  ImGui::PushItemWidth(ImGui::GetFontSize() * 9);
  log_slider("loosest [mm]", settings_.loosest, 1e-6, 1e-1, "%.2g");
  log_slider("tightest [mm]", settings_.tightest, 1e-8, 1e-2, "%.2g");
  input_int("steps per decade", settings_.per_decade, 1, 10);
  ImGui::PopItemWidth();
  constexpr bool kAnyPeer = kOcctPeersAvailable || kSislPeersAvailable;
  ImGui::BeginDisabled(!kAnyPeer);
  ImGui::Checkbox("Peers (OCCT, SISL)", &settings_.peers);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip(kAnyPeer ? "Open CASCADE's GeomAPI_PointsToBSpline (degree 3 and 3..8) and "
                                 "SISL's s1961 (degree 3 and the best of 3..8) fitted to dense "
                                 "contour samples, measured like ours; OCCT takes 1-2 s per "
                                 "tolerance and fit"
                               : "neither Open CASCADE nor SISL is available in this build");
  if (settings_.tightest >= settings_.loosest) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("The tightest tolerance must be below the loosest.");
    ImGui::PopStyleColor();
  }
  ImGui::BeginDisabled(settings_.tightest >= settings_.loosest);
  if (ImGui::Button(task_.busy() ? "Restart" : "Run study")) start();
  ImGui::EndDisabled();
  if (task_.busy()) {
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) task_.cancel();
    ImGui::ProgressBar(static_cast<float>(task_.progress()), ImVec2(-FLT_MIN, 0));
  }
  if (result_ && result_input_ && !(*result_input_ == cam_.current()))
    ImGui::TextDisabled("The design changed since this study: run it again.");
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", error_.c_str());
    ImGui::PopStyleColor();
  }
}

void StudyWorkspace::draw_table() {
  if (!result_) return;
  section("Arcs / control points (measured max error)");
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("study rows", 4, flags)) return;
  ImGui::TableSetupColumn("ε [mm]");
  ImGui::TableSetupColumn("quartic");
  ImGui::TableSetupColumn("RQB");
  ImGui::TableSetupColumn("cubic");
  ImGui::TableHeadersRow();
  for (const StudyRow& row : result_->rows) {
    ImGui::TableNextColumn();
    ImGui::Text("%.0e", row.tolerance);
    for (const StudyMethodResult* m : {&row.quartic, &row.rqb, &row.cubic}) {
      ImGui::TableNextColumn();
      ImGui::Text("%d / %d", m == &row.cubic ? m->points : m->arcs, m->control_points);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("degree %d, measured max radial error %.3g mm", m->degree,
                          m->max_radial_error);
    }
  }
  ImGui::EndTable();
  ImGui::TextDisabled("cubic: points interpolated / control points");
  ImGui::TextDisabled("computed in %.2f s", result_->seconds);
}

void StudyWorkspace::draw_peer_table() {
  if (!result_) return;
  section("Control points against the peers");
  if (!result_->peers)
    ImGui::TextDisabled("%s", missing_peers_note(StudyOptions{settings_.peers}).c_str());
  const int columns = result_->peers ? 9 : 3;
  const ImGuiTableFlags flags =
      ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("study peers", columns, flags)) return;
  ImGui::TableSetupColumn("ε [mm]");
  ImGui::TableSetupColumn("exact");
  ImGui::TableSetupColumn("deg 3");
  if (result_->peers) {
    ImGui::TableSetupColumn("OCCT 3");
    ImGui::TableSetupColumn("OCCT 3..8");
    ImGui::TableSetupColumn("SISL 3");
    ImGui::TableSetupColumn("SISL 3..8");
    ImGui::TableSetupColumn("exact/best");
    ImGui::TableSetupColumn("deg 3/best");
  }
  ImGui::TableHeadersRow();
  for (const StudyRow& row : result_->rows) {
    ImGui::TableNextColumn();
    ImGui::Text("%.0e", row.tolerance);
    for (const StudyMethodResult* m : {&row.exact, &row.degree3}) {
      ImGui::TableNextColumn();
      ImGui::Text("%d", m->control_points);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("degree %d, measured max radial error %.3g mm", m->degree,
                          m->max_radial_error);
    }
    if (!result_->peers) continue;
    const std::pair<const StudyPeerResult*, const char*> peers[] = {{&row.occt_degree3, "Tol3D"},
                                                                    {&row.occt_best, "Tol3D"},
                                                                    {&row.sisl_degree3, "eeps"},
                                                                    {&row.sisl_best, "eeps"}};
    for (const auto& [p, tolerance_name] : peers) {
      ImGui::TableNextColumn();
      if (!p->found) {
        ImGui::TextDisabled("-");
        continue;
      }
      ImGui::Text("%d", p->control_points);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("degree %d, measured max radial error %.3g mm, %s %.3g mm", p->degree,
                          p->max_radial_error, tolerance_name, p->peer_tolerance);
    }
    for (double ratio : {row.ratios.exact_to_best, row.ratios.degree3_to_best}) {
      ImGui::TableNextColumn();
      if (std::isfinite(ratio))
        ImGui::Text("%.2f", ratio);
      else
        ImGui::TextDisabled("-");
    }
  }
  ImGui::EndTable();
  ImGui::TextDisabled(
      "exact: the compacted exact form; best: the fewest of the OCCT and SISL fits");
}

void StudyWorkspace::draw_plots(ImVec2 size) {
  if (!result_) {
    ImGui::TextDisabled(task_.busy() ? "Running the study…" : "No study yet.");
    return;
  }
  if (!figures_)
    figures_ = {study_figure(*result_, cam_.document_name()), deviation_figure(*result_)};
  const float spacing = ImGui::GetStyle().ItemSpacing.y;
  draw_figure("study", figures_->first, views_[0], ImVec2(size.x, size.y * 0.62f - spacing));
  draw_figure("deviation", figures_->second, views_[1], ImVec2(size.x, size.y * 0.38f - spacing));
}

std::vector<ExportChoice> StudyWorkspace::export_choices() const {
  return {{{"study", "Export the study into a folder", "", cam_.document_name() + "-study"},
           "Study files (CSV, SVG, report.json) into a folder…",
           result_.has_value(), ""}};
}

void StudyWorkspace::export_to(const ExportRequest&, const std::filesystem::path& folder) {
  if (!result_) return;
  guarded(log(), "Export the study", [&] {
    const auto files = write_study_outputs(*result_, cam_.document_name(), folder);
    log().info("Wrote " + std::to_string(files.size()) + " study files to " + folder.string());
  });
}

std::string StudyWorkspace::numbers() const {
  std::ostringstream out;
  out.precision(10);
  out << "studied=" << (result_ ? 1 : 0) << "\n";
  if (!result_) return out.str();
  out << "tolerances=" << result_->rows.size() << "\n";
  const StudyRow& tightest =
      *std::min_element(result_->rows.begin(), result_->rows.end(),
                        [](const auto& a, const auto& b) { return a.tolerance < b.tolerance; });
  out << "tightest_tolerance_mm=" << tightest.tolerance << "\n";
  out << "tightest_quartic_control_points=" << tightest.quartic.control_points << "\n";
  out << "tightest_rqb_control_points=" << tightest.rqb.control_points << "\n";
  out << "tightest_cubic_control_points=" << tightest.cubic.control_points << "\n";
  out << "tightest_quartic_error_mm=" << tightest.quartic.max_radial_error << "\n";
  out << "tightest_exact_control_points=" << tightest.exact.control_points << "\n";
  out << "tightest_degree3_control_points=" << tightest.degree3.control_points << "\n";
  out << "peers=" << (result_->peers ? 1 : 0) << "\n";
  if (!result_->peers) return out.str();
  out << "tightest_occt_degree3_control_points=" << tightest.occt_degree3.control_points << "\n";
  out << "tightest_occt_best_control_points=" << tightest.occt_best.control_points << "\n";
  out << "tightest_sisl_degree3_control_points=" << tightest.sisl_degree3.control_points << "\n";
  out << "tightest_sisl_best_control_points=" << tightest.sisl_best.control_points << "\n";
  out << "tightest_exact_to_best_peer=" << tightest.ratios.exact_to_best << "\n";
  return out.str();
}

}  // namespace polarform::studio
