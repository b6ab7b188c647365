#include "jobs/vessel/vessel_plots.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/number_text.h"
#include "src/nurbs/tessellation.h"
#include "src/units.h"

namespace polarform {

namespace {

const char* kDesignColor = "#0072b2";
const char* kPresetColor = "#999999";
const char* kFlagColor = "#d55e00";
const char* kPresetRangeColor = "#0072b2";  // the preset's compressive range
constexpr double kCylinderShare = 0.15;  // of the head's meridian length, shown left of junction A

Series curvature_series(std::string label, const std::vector<CurvatureSample>& samples,
                        Series::Style style, std::string color) {
  Series s{std::move(label), {}, {}, style, std::move(color)};
  for (const CurvatureSample& c : samples)
    s.x.push_back(c.theta * kDegreesPerRadian), s.y.push_back(c.kappa);
  return s;
}

// σ_φ or σ_θ against the meridian arc length s (cylinder first, then junction A to the apex).
Series stress_series(std::string label, const StressProfile& p, bool hoop, Series::Style style,
                     std::string color) {
  Series s{std::move(label), {}, {}, style, std::move(color)};
  for (const StressSample& k : p.samples)
    s.x.push_back(k.s), s.y.push_back(hoop ? k.hoop_stress : k.meridional_stress);
  return s;
}

// Where σθ < 0: the design's ranges as bands, the preset's as labelled lines at their ends in the
// preset's colour (bands on bands would blend), each with its minimum annotated.
void mark_compressive_ranges(Plot& plot, const StressProfile& p, bool preset) {
  for (std::size_t i = 0; i < p.compressive_hoop.size(); ++i) {
    const CompressiveBand& b = p.compressive_hoop[i];
    if (preset) {
      // Labelled at its end: its start is often junction A, which has its own label.
      plot.add_vertical_line(b.s_from, "", kPresetRangeColor);
      plot.add_vertical_line(b.s_to, "preset σθ < 0 up to here", kPresetRangeColor);
    } else if (b.s_to > b.s_from) {
      plot.add_band(b.s_from, b.s_to, i == 0 ? "compressive hoop stress (design)" : "", kFlagColor);
    } else {  // a single angle (a flat head's junction, its only membrane sample)
      plot.add_vertical_line(b.s_from, "compressive hoop stress (design)", kFlagColor);
    }
    plot.add_annotation(0.5 * (b.s_from + b.s_to), b.min_hoop_stress,
                        std::string(preset ? "preset " : "") + "σθ " +
                            format_trimmed(b.min_hoop_stress, 1) + " MPa");
  }
}

// The meridian (x, z) = R(θ)(cos θ, sin θ) of a polar function at count + 1 angles.
Series meridian_series(std::string label, const PolarFunction& f, int count, Series::Style style,
                       std::string color) {
  Series s{std::move(label), {}, {}, style, std::move(color)};
  for (int i = 0; i <= count; ++i) {
    const double theta = f.start + (f.end - f.start) * i / count, R = f(theta);
    s.x.push_back(R * std::cos(theta)), s.y.push_back(R * std::sin(theta));
  }
  return s;
}

}  // namespace

Figure curvature_figure(const VesselSolveStage& r) {
  const VesselSolution& s = r.solution;
  Figure f(900, 680);
  const bool synthesised = r.design.head_design == HeadDesign::curvature;
  f.title = synthesised ? "Curvature along the head: prescribed targets and the synthesised profile"
            : s.exact   ? "Curvature along the exact head"
                        : "Curvature along the minimum-stress head";
  f.shared_x = true;
  Plot& kappa = f.add_panel();
  kappa.x_label = "polar angle θ [deg]";
  kappa.y_label = "curvature κ [1/mm]";
  kappa.x_range = AxisRange{0, 180};
  kappa.x_tick_step = 15;
  if (s.preset) {
    kappa.add(curvature_series(s.preset->shape.name, s.preset->curvature, Series::Style::dashed,
                               kPresetColor));
    for (std::size_t i = 0; i < s.preset->shape.jumps.size(); ++i)
      kappa.add_vertical_line(s.preset->shape.jumps[i].theta * kDegreesPerRadian,
                              i == 0 ? "preset curvature jumps" : "", kFlagColor);
  }
  kappa.add(curvature_series(synthesised ? "synthesised κ(θ)" : "κ(θ)", s.curvature,
                             Series::Style::line, kDesignColor));
  if (!synthesised) return f;
  Series targets{"targets κ_k", {}, {}, Series::Style::markers, "#009e73"};
  Series residuals{"", {}, {}, Series::Style::markers, "#009e73"};
  for (const TargetResidual& t : s.synthesis.targets) {
    targets.x.push_back(t.theta * kDegreesPerRadian), targets.y.push_back(t.target);
    residuals.x.push_back(t.theta * kDegreesPerRadian), residuals.y.push_back(t.residual());
  }
  kappa.add(std::move(targets));
  Plot& residual = f.add_panel();
  residual.y_label = "κ(θ_k) − κ_k [1/mm]";
  residual.add_horizontal_line(0.0);
  residual.add(std::move(residuals));
  return f;
}

Figure stress_figure(const VesselSolveStage& r) {
  const VesselSolution& s = r.solution;
  Figure f(900, 560);
  f.title = "Membrane stresses at " + format_trimmed(r.design.pressure, 3) + " MPa, wall " +
            format_trimmed(r.design.thickness, 3) + " mm";
  Plot& plot = f.add_panel();
  plot.x_label =
      "meridian arc length s from junction A [mm] (s < 0: the cylinder, constant stresses; apex "
      "at the right)";
  plot.y_label = "membrane stress [MPa]";
  // The head fills the width: of the cylinder, whose membrane stresses are constant, only a stub.
  // At the apex, the last sample; a flat head's only head sample is its junction: to its apex.
  const double last = s.stresses.samples.back().s;
  const double head_length =
      last > 0.0 ? last : arc_length(s.profile, 0.0, std::numbers::pi / 2, 64);
  plot.x_range = AxisRange{-kCylinderShare * head_length, head_length};
  if (s.preset) {
    const StressProfile& preset = s.preset->stresses;
    plot.add(stress_series("σφ preset", preset, false, Series::Style::dashed, "#56b4e9"));
    plot.add(stress_series("σθ preset", preset, true, Series::Style::dashed, "#e69f00"));
    mark_compressive_ranges(plot, preset, true);
  }
  plot.add(stress_series("σφ meridional", s.stresses, false, Series::Style::line, kDesignColor));
  plot.add(stress_series("σθ hoop", s.stresses, true, Series::Style::line, kFlagColor));
  mark_compressive_ranges(plot, s.stresses, false);
  plot.add_horizontal_line(0.0);
  plot.add_vertical_line(0.0, "junction A");
  return f;
}

Figure same_depth_figure(const VesselSolveStage& r) {
  const MinimumStressDesign& m = *r.solution.minimum_stress;
  Figure f(900, 680);
  f.title = "Heads of depth " + format_trimmed(r.solution.depth, 4) + " mm at " +
            format_trimmed(r.design.pressure, 3) + " MPa, wall " +
            format_trimmed(r.design.thickness, 3) + " mm";
  f.shared_x = true;
  const char* colors[] = {"#56b4e9", "#e69f00", "#cc79a7"};
  for (const bool hoop : {true, false}) {
    Plot& plot = f.add_panel();
    plot.x_label = "polar angle θ [deg] (junction at 0, apex at 90)";
    plot.y_label = hoop ? "hoop stress σθ [MPa]" : "meridional stress σφ [MPa]";
    plot.x_range = AxisRange{0, 90};
    plot.x_tick_step = 15;
    const auto series = [&](const HeadStressSummary& h, Series::Style style, std::string color) {
      Series out{h.name + ", peak |σ| " + format_trimmed(h.peak_stress, 4) + " MPa",
                 {},
                 {},
                 style,
                 std::move(color)};
      if (!hoop) out.label.clear();  // one legend, on the hoop panel
      for (const StressSample& k : h.stresses.samples)
        if (!k.on_cylinder)
          out.x.push_back(k.theta * kDegreesPerRadian),
              out.y.push_back(hoop ? k.hoop_stress : k.meridional_stress);
      return out;
    };
    for (std::size_t i = 0; i < m.same_depth.references.size(); ++i)
      plot.add(series(m.same_depth.references[i], Series::Style::dashed, colors[i % 3]));
    plot.add(series(m.stresses, Series::Style::line, kDesignColor));
    plot.add_horizontal_line(0.0);
  }
  return f;
}

Figure profile_figure(const VesselSolveStage& r, const VesselConversionStage* converted) {
  Figure f(800, 620);
  Plot& plot = f.add_panel();
  plot.equal_aspect = true;
  plot.x_label = "x, radial [mm]";
  plot.y_label = "z, axial [mm]";
  if (r.solution.preset)
    plot.add(meridian_series("preset", r.solution.preset->shape.profile, 720, Series::Style::dashed,
                             kPresetColor));
  if (converted) {
    const NurbsCurve2d& c = converted->profile;
    f.title = std::string(r.solution.exact ? "Exact head profile" : "Head profile") + ": degree " +
              std::to_string(c.degree()) + ", " + std::to_string(c.size()) + " control points, " +
              std::to_string(converted->arcs) + " arcs";
    // The polygon under the curve; its points marked only while they stay apart.
    const auto polygon_style = c.size() <= 60 ? Series::Style::line_markers : Series::Style::line;
    Series polygon{"control polygon", {}, {}, polygon_style, "#cc79a7"};
    for (const Eigen::Vector2d& p : c.control_points())
      polygon.x.push_back(p.x()), polygon.y.push_back(p.y());
    plot.add(std::move(polygon));
    Series curve{"profile (NURBS)", {}, {}, Series::Style::line, kDesignColor};
    for (const Eigen::Vector2d& p : tessellate(c, 2000).points)
      curve.x.push_back(p.x()), curve.y.push_back(p.y());
    plot.add(std::move(curve));
  } else {
    f.title = "Head profile (not converted)";
    plot.add(meridian_series("profile R(θ)", r.solution.profile, 720, Series::Style::line,
                             kDesignColor));
  }
  // A stub of the cylinder below each junction, a quarter of the radius long.
  const double x = converted ? converted->surfaces.junction_radius : r.solution.junction_radius;
  const double stub = std::min(r.design.length, x / 4);
  plot.add({"cylinder", {x, x}, {0.0, -stub}, Series::Style::line, "#444444"});
  plot.add({"", {-x, -x}, {0.0, -stub}, Series::Style::line, "#444444"});
  plot.add_horizontal_line(0.0, "junction plane");
  return f;
}

}  // namespace polarform
