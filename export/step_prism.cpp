#include "export/step_prism.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "export/exchange_geometry.h"
#include "export/step_geometry.h"
#include "export/step_product.h"
#include "src/error.h"
#include "src/nurbs/extrusion.h"

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

// The loop of a wall face: the low edge, the seam up, the high edge back and the seam down, the
// face on the left seen from its normal's side.
int wall_loop(StepTopology& topo, int low, int seam, int high, bool outward) {
  if (outward) return topo.loop({{low, true}, {seam, true}, {high, false}, {seam, false}});
  return topo.loop({{seam, true}, {high, true}, {seam, false}, {low, false}});
}

}  // namespace

NurbsCurve2d counter_clockwise_profile(const NurbsCurve2d& profile, double tolerance,
                                       const std::string& what) {
  require_exchangeable(profile.degree(), profile.knots(), what);
  const Eigen::Vector2d gap = profile.point(profile.back()) - profile.point(profile.front());
  if (gap.norm() > tolerance)
    throw InputError(what + ": not closed, its ends are " + std::to_string(gap.norm()) +
                     " mm apart (resolution " + std::to_string(tolerance) + " mm)");
  const double area = signed_area(profile);
  if (std::abs(area) <= tolerance * tolerance) throw InputError(what + ": encloses no area");
  return area > 0 ? profile : reversed(profile);
}

// The sample minimum of the distance refined by golden-section search (Kiefer 1953) between the
// neighbouring samples; the winding from the signed angles the sampled chords subtend.
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
    if (c.point(m1).norm() < c.point(m2).norm())
      hi = m2;
    else
      lo = m1;
  }
  best = std::min(best, c.point(0.5 * (lo + hi)).norm());
  return {static_cast<int>(std::lround(angle / (2.0 * std::numbers::pi))), best};
}

StepWall step_profile_wall(StepFile& f, StepTopology& topo, const NurbsCurve2d& ccw_profile,
                           double z0, double z1, bool outward, double tolerance) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const NurbsCurve3d curve = lift_to_3d(ccw_profile);
  const NurbsCurve3d low_curve = translated(curve, z0 * z);
  const Eigen::Vector3d start = low_curve.point(low_curve.front());
  const int v_low = topo.vertex(start), v_high = topo.vertex(start + (z1 - z0) * z);
  StepWall w;
  w.low = topo.edge(v_low, v_low, step_bspline_curve(f, low_curve, tolerance, ""));
  w.high =
      topo.edge(v_high, v_high, step_bspline_curve(f, translated(curve, z1 * z), tolerance, ""));
  const int seam = topo.edge(v_low, v_high, step_line(f, start, z));
  // Its normal C'(u) x z points out of the enclosed region for a counter-clockwise C.
  const NurbsSurface side = extrude(curve, z, z0, z1);
  w.face = topo.face({{wall_loop(topo, w.low, seam, w.high, outward), true}},
                     step_bspline_surface(f, side, tolerance), outward);
  return w;
}

StepWall step_circle_wall(StepFile& f, StepTopology& topo, double radius, double z0, double z1,
                          bool outward) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d b = radius * x + z0 * z;
  const int v_low = topo.vertex(b), v_high = topo.vertex(b + (z1 - z0) * z);
  StepWall w;
  w.low = topo.edge(v_low, v_low, step_circle(f, step_axis2(f, z0 * z, z, x), radius));
  w.high = topo.edge(v_high, v_high, step_circle(f, step_axis2(f, z1 * z, z, x), radius));
  const int seam = topo.edge(v_low, v_high, step_line(f, b, z));
  const int cylinder =
      step_cylindrical_surface(f, step_axis2(f, Eigen::Vector3d::Zero(), z, x), radius);
  w.face = topo.face({{wall_loop(topo, w.low, seam, w.high, outward), true}}, cylinder, outward);
  return w;
}

std::string step_solid_file(StepFile& f, int context, const std::vector<std::string>& faces,
                            const std::string& name, const StepHeader& header) {
  // ISO 10303-42 closed_shell, manifold_solid_brep; ISO 10303-514
  // advanced_brep_shape_representation.
  const int shell = f.add("CLOSED_SHELL(''," + step_list(faces) + ")");
  const int solid =
      f.add("MANIFOLD_SOLID_BREP(" + step_string(name, "solid name") + "," + step_ref(shell) + ")");
  const int representation = f.add(
      "ADVANCED_BREP_SHAPE_REPRESENTATION(" + step_string(name, "solid name") + ",(" +
      step_ref(solid) + "," + step_ref(step_origin_placement(f)) + ")," + step_ref(context) + ")");
  step_product(f, name, representation);
  return f.str(header);
}

}  // namespace polarform
