#include "ui/studio/svaj_panel.h"

#include <cmath>
#include <numbers>
#include <string>

#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/segment_edits.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr const char* kNames[5] = {"displacement", "velocity", "acceleration", "jerk",
                                   "pressure angle"};
constexpr const char* kPerRadian[5] = {"s [mm]", "v [mm/rad]", "a [mm/rad²]", "j [mm/rad³]",
                                       "φ [°]"};
constexpr const char* kTime[5] = {"s [mm]", "v [mm/s]", "a [m/s²]", "j [m/s³]", "φ [°]"};

}  // namespace

void SvajPanel::convert_units(const CamResults& r, const CamViewSettings& view) {
  // At constant cam speed ω, d^k s/dt^k = ω^k d^k s/dθ^k; accelerations and jerks in m.
  const double w = 2 * std::numbers::pi * r.design.rpm / 60.0;
  unit_factor_ = view.units == MotionUnits::time
                     ? std::array<double, 4>{1, w, w * w / 1000, w * w * w / 1000}
                     : std::array<double, 4>{1, 1, 1, 1};
  const std::vector<double>* raw[3] = {&r.motion.v, &r.motion.a, &r.motion.j};
  for (int k = 0; k < 3; ++k) {
    scaled_[k].resize(raw[k]->size());
    for (std::size_t i = 0; i < raw[k]->size(); ++i)
      scaled_[k][i] = (*raw[k])[i] * unit_factor_[k + 1];
  }
}

bool SvajPanel::draw(const CamResults& r, const CamViewSettings& view,
                     std::vector<SegmentSpec>& segments, ImVec2 size) {
  convert_units(r, view);
  crosshair_.next_frame();
  const bool plate = r.plate.has_value();
  const int plots = 5;
  const float height = std::max(60.0f, size.y / plots - ImGui::GetStyle().ItemSpacing.y);
  const std::vector<double>* data[5] = {&r.motion.s, &scaled_[0], &scaled_[1], &scaled_[2],
                                        &r.motion.pressure_deg};
  bool changed = false;
  for (int k = 0; k < plots; ++k) {
    PlotSpec spec;
    spec.id = kNames[k];
    spec.y_label = (view.units == MotionUnits::time ? kTime : kPerRadian)[k];
    spec.x_label = "cam angle θ [°]";
    spec.x_tick_labels = k == plots - 1;
    spec.x_extent = AxisRange{0.0, 360.0};
    spec.lines.push_back({kNames[k], r.motion.theta_deg, *data[k], palette_color(k), 2.0f});
    for (std::size_t b = 0; b < r.boundaries_deg.size(); ++b) {
      const auto& seg = r.program->segments();
      spec.markers.push_back({r.boundaries_deg[b],
                              "boundary '" + seg[b].name() + "' | '" + seg[b + 1].name() + "'",
                              color::boundary, true});
    }
    if (k < 4) {
      for (const ContinuityIssue& issue : r.issues) {
        if (issue.derivative != k) continue;
        const double f = unit_factor_[k];
        for (double x : {issue.angle * kDegreesPerRadian, issue.angle == 0.0 ? 360.0 : -1.0}) {
          if (x < 0) continue;
          spec.points.push_back({x, issue.before_value * f, issue.message(), color::error});
          spec.points.push_back({x, issue.after_value * f, issue.message(), color::error});
          spec.bands.push_back({x - 0.6, x + 0.6, color::error_band});
        }
      }
    } else {
      const double limit = view.pressure_angle_limit * kDegreesPerRadian;
      if (plate && r.design.follower.kind != FollowerKind::FlatFaced) {
        spec.levels.push_back({limit, "limit " + number_text(limit) + "°", color::error});
        spec.levels.push_back({-limit, "", color::error});
      }
      if (!plate) spec.title = "at the pitch radius";
    }
    ImGui::PushID(k);
    const PlotEvents events =
        draw_plot(spec, x_view_, y_views_[k], ImVec2(size.x, height), &crosshair_);
    ImGui::PopID();
    // The plots may show the last valid design while the edited one has fewer boundaries.
    if (events.dragged_marker >= 0 &&
        events.dragged_marker + 1 < static_cast<int>(segments.size())) {
      set_boundary(segments, events.dragged_marker + 1, events.marker_x * kRadiansPerDegree);
      changed = true;
    }
  }
  return changed;
}

}  // namespace polarform::studio
