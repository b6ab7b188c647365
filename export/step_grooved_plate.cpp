#include "export/step_grooved_plate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "export/step_geometry.h"
#include "export/step_prism.h"
#include "export/step_product.h"
#include "export/step_topology.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// The largest distance of the profile from the origin, sampled (only compared with margins).
double reach(const NurbsCurve2d& c) {
  double r = 0.0;
  constexpr int kSamples = 4096;
  for (int i = 0; i <= kSamples; ++i)
    r = std::max(r, c.point(c.front() + (c.back() - c.front()) * i / kSamples).norm());
  return r;
}

// The profile sampled as (polar angle, radius), sorted by angle.
std::vector<std::pair<double, double>> polar_samples(const NurbsCurve2d& c) {
  constexpr int kSamples = 4096;
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i < kSamples; ++i) {
    const Eigen::Vector2d p = c.point(c.front() + (c.back() - c.front()) * i / kSamples);
    out.emplace_back(std::atan2(p.y(), p.x()), p.norm());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The smallest radius of the outer flank minus that of the inner at the inner's sampled polar
// angles (the outer's radius interpolated linearly between its neighbouring samples).
double least_radial_gap(const NurbsCurve2d& inner, const NurbsCurve2d& outer) {
  const std::vector<std::pair<double, double>> o = polar_samples(outer);
  double gap = std::numeric_limits<double>::infinity();
  for (const auto& [angle, r] : polar_samples(inner)) {
    const auto hi = std::lower_bound(o.begin(), o.end(), std::pair{angle, -1.0});
    const auto& b = hi == o.end() ? o.front() : *hi;
    const auto& a = hi == o.begin() ? o.back() : *(hi - 1);
    const double span = std::remainder(b.first - a.first, 2 * std::numbers::pi);
    const double t = span != 0 ? std::remainder(angle - a.first, 2 * std::numbers::pi) / span : 0;
    gap = std::min(gap, a.second + t * (b.second - a.second) - r);
  }
  return gap;
}

void check_dimensions(const GroovedPlate& p) {
  if (!std::isfinite(p.thickness) || !(p.thickness > 0))
    throw InputError("grooved plate thickness " + number_text(p.thickness) +
                     " mm: expected a finite value > 0");
  if (!std::isfinite(p.depth) || !(p.depth > 0 && p.depth < p.thickness))
    throw InputError("groove-depth " + number_text(p.depth) +
                     " mm: expected more than 0 and less than the plate thickness " +
                     number_text(p.thickness) + " mm");
  if (!std::isfinite(p.rim) || !(p.rim > 0))
    throw InputError("grooved plate rim " + number_text(p.rim) +
                     " mm: expected a finite value > 0");
  if (p.bore_diameter && (!std::isfinite(*p.bore_diameter) || !(*p.bore_diameter > 0)))
    throw InputError("grooved plate bore diameter " + number_text(*p.bore_diameter) +
                     " mm: expected a finite value > 0");
}

}  // namespace

std::string step_grooved_plate_solid(const GroovedPlate& p, const std::string& name,
                                     const StepHeader& header) {
  const double tol = header.resolution;
  check_dimensions(p);
  const NurbsCurve2d inner = counter_clockwise_profile(p.inner, tol, "groove inner flank");
  const NurbsCurve2d outer = counter_clockwise_profile(p.outer, tol, "groove outer flank");
  const auto [inner_winding, inner_clearance] = winding_and_clearance(inner);
  const int outer_winding = winding_and_clearance(outer).first;
  if (inner_winding != 1 || outer_winding != 1)
    throw InputError("grooved plate: the flanks must wind once around the cam axis (the origin)");
  if (const double gap = least_radial_gap(inner, outer); !(gap > tol))
    throw InputError(
        "grooved plate: the outer flank must lie outside the inner flank at every "
        "polar angle; their radial gap falls to " +
        number_text(gap) + " mm");
  const double radius = reach(outer) + p.rim;
  const double bore = p.bore_diameter.value_or(0.0) / 2;
  if (p.bore_diameter && !(bore < inner_clearance - tol))
    throw InputError("grooved plate bore diameter " + number_text(*p.bore_diameter) +
                     " mm: the bore must lie inside the inner flank, whose closest point is " +
                     number_text(inner_clearance) + " mm from the axis");

  StepFile f;
  StepTopology topo(f, tol);
  const int context = step_context(f, tol);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  const double floor = p.thickness - p.depth;

  // The walls: the rim and the inner flank face outwards, the outer flank and the bore inwards.
  const StepWall rim = step_circle_wall(f, topo, radius, 0.0, p.thickness, true);
  const StepWall inner_wall = step_profile_wall(f, topo, inner, floor, p.thickness, true, tol);
  const StepWall outer_wall = step_profile_wall(f, topo, outer, floor, p.thickness, false, tol);
  std::vector<std::string> faces = {step_ref(rim.face), step_ref(inner_wall.face),
                                    step_ref(outer_wall.face)};

  // Planar faces: loops counter-clockwise around an outer bound seen from the normal's side.
  std::vector<StepTopology::Bound> bottom = {{topo.loop({{rim.low, false}}), true}};
  std::vector<StepTopology::Bound> island = {{topo.loop({{inner_wall.high, true}}), true}};
  if (p.bore_diameter) {
    const StepWall bore_wall = step_circle_wall(f, topo, bore, 0.0, p.thickness, false);
    faces.push_back(step_ref(bore_wall.face));
    bottom.push_back({topo.loop({{bore_wall.low, true}}), false});
    island.push_back({topo.loop({{bore_wall.high, false}}), false});
  }
  const auto plane = [&](double level) { return step_plane(f, step_axis2(f, level * z, z, x)); };
  const int top_plane = plane(p.thickness);
  faces.push_back(step_ref(topo.face(bottom, plane(0.0), false)));
  faces.push_back(step_ref(topo.face(
      {{topo.loop({{rim.high, true}}), true}, {topo.loop({{outer_wall.high, false}}), false}},
      top_plane, true)));
  faces.push_back(step_ref(topo.face(island, top_plane, true)));
  faces.push_back(step_ref(topo.face(
      {{topo.loop({{outer_wall.low, true}}), true}, {topo.loop({{inner_wall.low, false}}), false}},
      plane(floor), true)));
  return step_solid_file(f, context, faces, name, header);
}

}  // namespace polarform
