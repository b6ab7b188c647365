#include "ui/studio/cam_scan_panel.h"

#include <array>
#include <string_view>

#include "jobs/scan_cam/scan_cam_plots.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/colors.h"
#include "ui/studio/guarded.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr std::array<std::string_view, 3> kFollowers = {"knife-edge", "roller", "flat-faced"};
constexpr std::array<FollowerKind, 3> kKinds = {FollowerKind::KnifeEdge, FollowerKind::Roller,
                                                FollowerKind::FlatFaced};
constexpr std::array<std::string_view, 2> kRotations = {"counter-clockwise", "clockwise"};

// "60.000° ± 0.004°"
std::string angle_with_sd(double radians, double sd) {
  return degrees_text(radians) + " ± " + number_text(sd * kDegreesPerRadian) + "°";
}

}  // namespace

ScanCamJobOptions CamScanPanel::options() const {
  ScanCamJobOptions o;
  o.follower = Follower{kKinds[follower_], 0.0, follower_ == 1 ? roller_radius_ : 0.0};
  o.rotation = clockwise_ ? Rotation::Clockwise : Rotation::CounterClockwise;
  return o;
}

void CamScanPanel::start(const std::filesystem::path& scan) {
  result_.reset();
  figure_.reset();
  task_.start(
      [scan, options = options()](TaskControl&) { return run_scan_cam_job(scan, options); });
}

void CamScanPanel::reset() {
  task_.cancel();
  result_.reset();
  figure_.reset();
}

void CamScanPanel::draw_controls(const std::filesystem::path& scan) {
  bool changed = combo("follower", follower_, kFollowers);
  if (follower_ == 1)
    changed |= drag_number("roller radius [mm]", roller_radius_, 0.05, 0.001, 1e5, "%.3f");
  int rotation = clockwise_ ? 1 : 0;
  if (combo("rotation", rotation, kRotations)) {
    clockwise_ = rotation == 1;
    changed = true;
  }
  if (changed) reset();  // the result was for other settings
  if (task_.busy()) {
    ImGui::TextDisabled("Recovering the cam design…");  // the job reports no progress
    return;
  }
  if (ImGui::Button("Recover the cam design", ImVec2(-FLT_MIN, 0))) start(scan);
  help_marker(
      "polarform scan-cam: the follower motion read from the profile, segmented into dwells, rises "
      "and returns, each law identified with its boundaries and lift (docs/cli-fit.md)");
  if (!result_) return;
  const ScanCamJobResult& r = *result_;
  if (!r.design) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("No design recovered: %s", r.design_failure.c_str());
    ImGui::PopStyleColor();
    return;
  }
  const RecoveredDesign& d = *r.design;
  if (ImGui::BeginTable("recovered", 4,
                        ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    for (const char* h : {"motion", "from", "to", "lift"}) ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const IdentifiedMotion& m : d.motions) {
      const LawFit& law = m.law();
      ImGui::TableNextColumn();
      ImGui::Text("%s, %s%s", m.kind == SegmentKind::Rise ? "rise" : "return",
                  std::string(motion_law_name(law.shape.law)).c_str(),
                  m.indistinguishable.empty() ? "" : " (?)");
      if (!m.indistinguishable.empty() && ImGui::IsItemHovered()) {
        std::string others;
        for (std::size_t k : m.indistinguishable)
          others += (others.empty() ? "" : ", ") +
                    std::string(motion_law_name(m.candidates[k].shape.law));
        ImGui::SetTooltip("the scan cannot tell it from: %s", others.c_str());
      }
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(angle_with_sd(law.start, law.sd.size() > 0 ? law.sd[0] : 0.0).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(angle_with_sd(law.end, law.sd.size() > 1 ? law.sd[1] : 0.0).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%s ± %s mm", number_text(std::abs(law.lift)).c_str(),
                  number_text(law.sd.size() > 3 ? law.sd[3] : 0.0).c_str());
    }
    ImGui::EndTable();
  }
  ImGui::TextWrapped("re-designed cam against the scan points (normal): max %s mm, rms %s mm",
                     number_text(d.deviation.point_normal_stats.max).c_str(),
                     number_text(d.deviation.point_normal_stats.rms).c_str());
  static constexpr const char* kDerivatives[] = {"s", "v", "a", "j"};
  const int resolved = r.resolution.resolved_order;
  ImGui::TextWrapped(
      "the scan resolves the motion up to %s",
      resolved < 0 ? "nothing (noise above the signal)" : kDerivatives[std::min(resolved, 3)]);
}

void CamScanPanel::update(MessageLog& log) {
  if (auto outcome = task_.poll()) {
    if (outcome->value) {
      result_ = std::move(outcome->value);
      log.info("Recovered the cam design from " + result_->input.filename().string() + " in " +
               number_text(outcome->seconds) + " s");
    } else if (outcome->error) {
      log.error(failure_text("Recover the cam design", outcome->error));
    }
  }
}

const ScanCamJobResult& CamScanPanel::ensure(const std::filesystem::path& scan) {
  if (!result_) {
    task_.cancel();
    result_ = run_scan_cam_job(scan, options());
    figure_.reset();
  }
  return *result_;
}

void CamScanPanel::draw_result(ImVec2 size) {
  if (!result_) {
    ImGui::TextDisabled(task_.busy() ? "Recovering the cam design…"
                                     : "Recover the cam design on the left.");
    return;
  }
  if (!figure_) figure_ = scan_svaj_figure(*result_);
  draw_figure("cam motion", *figure_, view_, size);
}

}  // namespace polarform::studio
