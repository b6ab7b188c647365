#include "export/step_solid.h"

#include <cmath>
#include <numbers>

#include "export/atomic_file.h"
#include "export/exchange_geometry.h"
#include "export/step_geometry.h"
#include "export/step_product.h"
#include "export/step_topology.h"
#include "src/error.h"

namespace polarform {

namespace {

constexpr int kSamplesPerSpan = 64;

// Enclosed signed area 1/2 * integral (x y' - y x') du (Green's theorem), midpoint rule per knot
// span (only its sign and order of magnitude are used).
double signed_area(const NurbsCurve2d& c) {
  double area = 0.0;
  const Knots& k = c.knots();
  for (int s = c.degree(); s < c.size(); ++s) {
    const double h = (k[s + 1] - k[s]) / kSamplesPerSpan;
    for (int i = 0; i < kSamplesPerSpan; ++i) {
      const auto d = c.derivatives(k[s] + (i + 0.5) * h, 1);
      area += 0.5 * (d[0].x() * d[1].y() - d[0].y() * d[1].x()) * h;
    }
  }
  return area;
}

// Winding number of the sampled profile around the origin (sum of the signed angles its chords
// subtend) and the distance from the origin to the profile: the sample minimum refined by
// golden-section search (Kiefer 1953) between the neighbouring samples.
std::pair<int, double> winding_and_clearance(const NurbsCurve2d& c) {
  std::vector<double> us;
  const Knots& k = c.knots();
  for (int s = c.degree(); s < c.size(); ++s)
    for (int i = 0; i < kSamplesPerSpan; ++i)
      if (k[s + 1] > k[s]) us.push_back(k[s] + (k[s + 1] - k[s]) * i / kSamplesPerSpan);
  us.push_back(c.back());
  double angle = 0.0, best = c.point(us[0]).norm();
  std::size_t best_i = 0;
  for (std::size_t i = 1; i < us.size(); ++i) {
    const Eigen::Vector2d a = c.point(us[i - 1]), b = c.point(us[i]);
    angle += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (b.norm() < best) best = b.norm(), best_i = i;
  }
  double lo = us[best_i > 0 ? best_i - 1 : 0], hi = us[std::min(best_i + 1, us.size() - 1)];
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 100; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (c.point(m1).norm() < c.point(m2).norm()) hi = m2;
    else lo = m1;
  }
  best = std::min(best, c.point(0.5 * (lo + hi)).norm());
  return {static_cast<int>(std::lround(angle / (2.0 * std::numbers::pi))), best};
}

}  // namespace

std::string step_extruded_solid(const NurbsCurve2d& closed_profile, double thickness,
                                std::optional<double> bore_diameter, const std::string& name,
                                const StepHeader& header) {
  const double tol = header.resolution;
  require_exchangeable(closed_profile.degree(), closed_profile.knots(), "STEP solid profile");
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw InputError("STEP solid thickness " + std::to_string(thickness) +
                     " mm: expected a finite value > 0");
  const Eigen::Vector2d gap =
      closed_profile.point(closed_profile.back()) - closed_profile.point(closed_profile.front());
  if (gap.norm() > tol)
    throw InputError("STEP solid profile: not closed, its ends are " + std::to_string(gap.norm()) +
                     " mm apart (resolution " + std::to_string(tol) + " mm)");
  const double area = signed_area(closed_profile);
  if (std::abs(area) <= tol * tol)
    throw InputError("STEP solid profile: encloses no area");
  const NurbsCurve2d profile = area > 0 ? closed_profile : reversed(closed_profile);

  const double r = bore_diameter.value_or(0.0) / 2.0;
  if (bore_diameter) {
    if (!(r > 0.0) || !std::isfinite(r))
      throw InputError("STEP solid bore_diameter " + std::to_string(*bore_diameter) +
                       " mm: expected a finite value > 0");
    const auto [winding, clearance] = winding_and_clearance(profile);
    if (winding != 1)
      throw InputError("STEP solid bore: the profile does not enclose the bore axis (the origin)");
    if (r >= clearance - tol)
      throw InputError("STEP solid bore_diameter " + std::to_string(*bore_diameter) +
                       " mm: the bore must lie inside the profile, whose closest point is " +
                       std::to_string(clearance) + " mm from the axis");
  }

  StepFile f;
  StepTopology topo(f, tol);
  const int context = step_context(f, tol);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d top_offset = thickness * z;

  // Profile edges: bottom and top copies of the counter-clockwise profile, joined by a seam line
  // at the profile's start point.
  const NurbsCurve3d bottom_curve = lift_to_3d(profile);
  const Eigen::Vector3d start = bottom_curve.point(bottom_curve.front());
  const int v_bottom = topo.vertex(start), v_top = topo.vertex(start + top_offset);
  const int bottom_spline = step_bspline_curve(f, bottom_curve, tol, "");
  const int top_spline = step_bspline_curve(f, translated(bottom_curve, top_offset), tol, "");
  const int e_bottom = topo.edge(v_bottom, v_bottom, bottom_spline);
  const int e_top = topo.edge(v_top, v_top, top_spline);
  const int e_seam = topo.edge(v_bottom, v_top, step_line(f, start, z));

  // Side face: S(u, v) = C(u) + v z for v in [0, thickness], written as the exactly equivalent
  // B-spline surface of degree (p, 1) (Open CASCADE integrates mass properties over a
  // SURFACE_OF_LINEAR_EXTRUSION with errors of a few percent). Its normal C'(u) x z points
  // outwards for a counter-clockwise C; its loop runs counter-clockwise in (u, v).
  NurbsSurface::Points side_points;
  std::vector<double> side_weights;
  for (int i = 0; i < profile.size(); ++i)
    for (double z_level : {0.0, thickness}) {
      side_points.push_back(bottom_curve.control_point(i) + z_level * z);
      side_weights.push_back(profile.weight(i));
    }
  const NurbsSurface side(profile.degree(), 1, profile.knots(), {0.0, 0.0, thickness, thickness},
                          side_points, side_weights);
  const int side_surface = step_bspline_surface(f, side, tol);
  std::vector<std::string> faces;
  faces.push_back(step_ref(topo.face(
      {{topo.loop({{e_bottom, true}, {e_seam, true}, {e_top, false}, {e_seam, false}}), true}},
      side_surface, true)));

  // Bottom face (normal -z) and top face (normal +z); the profile is their outer bound.
  const int bottom_plane = step_plane(f, step_axis2(f, Eigen::Vector3d::Zero(), z, x));
  const int top_plane = step_plane(f, step_axis2(f, top_offset, z, x));
  std::vector<StepTopology::Bound> bottom_bounds = {{topo.loop({{e_bottom, false}}), true}};
  std::vector<StepTopology::Bound> top_bounds = {{topo.loop({{e_top, true}}), true}};

  if (bore_diameter) {
    // Bore: circles of radius r around z at both ends, a seam line at (r, 0), and the cylinder
    // face whose material lies outside (face normal towards the axis: same_sense .F.).
    const Eigen::Vector3d b = r * x;
    const int v_bore_bottom = topo.vertex(b), v_bore_top = topo.vertex(b + top_offset);
    const int e_bore_bottom = topo.edge(
        v_bore_bottom, v_bore_bottom,
        step_circle(f, step_axis2(f, Eigen::Vector3d::Zero(), z, x), r));
    const int e_bore_top =
        topo.edge(v_bore_top, v_bore_top, step_circle(f, step_axis2(f, top_offset, z, x), r));
    const int e_bore_seam = topo.edge(v_bore_bottom, v_bore_top, step_line(f, b, z));
    const int cylinder =
        step_cylindrical_surface(f, step_axis2(f, Eigen::Vector3d::Zero(), z, x), r);
    faces.push_back(step_ref(topo.face({{topo.loop({{e_bore_seam, true},
                                                    {e_bore_top, true},
                                                    {e_bore_seam, false},
                                                    {e_bore_bottom, false}}),
                                         true}},
                                       cylinder, false)));
    bottom_bounds.push_back({topo.loop({{e_bore_bottom, true}}), false});
    top_bounds.push_back({topo.loop({{e_bore_top, false}}), false});
  }
  faces.push_back(step_ref(topo.face(bottom_bounds, bottom_plane, false)));
  faces.push_back(step_ref(topo.face(top_bounds, top_plane, true)));

  // ISO 10303-42 closed_shell, manifold_solid_brep; ISO 10303-514 advanced_brep_shape_representation.
  const int shell = f.add("CLOSED_SHELL(''," + step_list(faces) + ")");
  const int solid = f.add("MANIFOLD_SOLID_BREP(" + step_string(name, "solid name") + "," +
                          step_ref(shell) + ")");
  const int representation =
      f.add("ADVANCED_BREP_SHAPE_REPRESENTATION(" + step_string(name, "solid name") + ",(" +
            step_ref(solid) + "," + step_ref(step_origin_placement(f)) + ")," +
            step_ref(context) + ")");
  step_product(f, name, representation);
  return f.str(header);
}

void write_step_extruded_solid(const std::filesystem::path& path, const NurbsCurve2d& closed_profile,
                               double thickness, std::optional<double> bore_diameter,
                               const std::string& name, const StepHeader& header) {
  StepHeader h = header;
  if (h.file_name.empty()) h.file_name = path.filename().string();
  write_file_atomically(path, step_extruded_solid(closed_profile, thickness, bore_diameter, name, h));
}

}  // namespace polarform
