#include "export/step_geometry.h"

#include "export/exchange_geometry.h"

namespace polarform {

namespace {

std::string reals(const Eigen::Vector3d& v) {
  return step_list({step_real(v.x()), step_real(v.y()), step_real(v.z())});
}

// Distinct knots and their multiplicities, ISO 10303-42 b_spline_curve_with_knots.
std::pair<std::string, std::string> knot_lists(const Knots& knots) {
  std::vector<std::string> mult, value;
  for (const Breakpoint& b : breakpoints(knots)) {
    mult.push_back(std::to_string(b.multiplicity));
    value.push_back(step_real(b.value));
  }
  return {step_list(mult), step_list(value)};
}

// closed_curve: .T. for a closed curve whose end control points coincide homogeneously (clamped
// with equal end weights) or whose knots and points wrap periodically; .F. otherwise. A closed curve
// of neither kind is deliberately written .F. (ISO 10303-42 calls closed_curve informational):
// Open CASCADE 7.6 re-forms every B-spline whose closed_curve is not .F. as periodic by dropping
// the last control point and its weight, which changes such a curve.
std::string closed_logical(const NurbsCurve3d& c, double tolerance) {
  if (!is_closed(c, tolerance)) return ".F.";
  const int p = c.degree(), n = c.size();
  const Knots& k = c.knots();
  const bool clamped = k[0] == k[p] && k[n] == k[n + p];
  if (has_periodic_structure(c.homogeneous()) || (clamped && c.weight(0) == c.weight(n - 1)))
    return ".T.";
  return ".F.";
}

}  // namespace

int step_point(StepFile& f, const Eigen::Vector3d& p) {
  return f.add("CARTESIAN_POINT(''," + reals(f.placement ? Eigen::Vector3d(*f.placement * p) : p) +
               ")");
}

int step_direction(StepFile& f, const Eigen::Vector3d& d) {
  return f.add("DIRECTION(''," +
               reals(f.placement ? Eigen::Vector3d(f.placement->linear() * d) : d) + ")");
}

int step_axis2(StepFile& f, const Eigen::Vector3d& origin, const Eigen::Vector3d& z,
               const Eigen::Vector3d& x) {
  const int o = step_point(f, origin), a = step_direction(f, z), r = step_direction(f, x);
  return f.add("AXIS2_PLACEMENT_3D(''," + step_ref(o) + "," + step_ref(a) + "," + step_ref(r) +
               ")");
}

int step_line(StepFile& f, const Eigen::Vector3d& p, const Eigen::Vector3d& d) {
  const int pt = step_point(f, p), dir = step_direction(f, d);
  const int vec = f.add("VECTOR(''," + step_ref(dir) + "," + step_real(1.0) + ")");
  return f.add("LINE(''," + step_ref(pt) + "," + step_ref(vec) + ")");
}

int step_circle(StepFile& f, int axis2, double radius) {
  return f.add("CIRCLE(''," + step_ref(axis2) + "," + step_real(radius) + ")");
}

int step_plane(StepFile& f, int axis2) { return f.add("PLANE(''," + step_ref(axis2) + ")"); }

int step_cylindrical_surface(StepFile& f, int axis2, double radius) {
  return f.add("CYLINDRICAL_SURFACE(''," + step_ref(axis2) + "," + step_real(radius) + ")");
}

int step_bspline_curve(StepFile& f, const NurbsCurve3d& c, double tolerance,
                       const std::string& name) {
  std::vector<std::string> points;
  for (int i = 0; i < c.size(); ++i) points.push_back(step_ref(step_point(f, c.control_point(i))));
  const auto [mult, knots] = knot_lists(c.knots());
  const std::string degree = std::to_string(c.degree());
  const std::string closed = closed_logical(c, tolerance);
  const std::string label = step_string(name, "curve name");
  if (!c.is_rational())  // ISO 10303-42 b_spline_curve_with_knots
    return f.add("B_SPLINE_CURVE_WITH_KNOTS(" + label + "," + degree + "," + step_list(points) +
                 ",.UNSPECIFIED.," + closed + ",.U.," + mult + "," + knots + ",.UNSPECIFIED.)");
  std::vector<std::string> weights;
  for (int i = 0; i < c.size(); ++i) weights.push_back(step_real(c.weight(i)));
  // ISO 10303-42 rational_b_spline_curve: complex instance, supertypes in alphabetical order
  // (ISO 10303-21 external mapping).
  return f.add("(BOUNDED_CURVE() B_SPLINE_CURVE(" + degree + "," + step_list(points) +
               ",.UNSPECIFIED.," + closed + ",.U.) B_SPLINE_CURVE_WITH_KNOTS(" + mult + "," +
               knots + ",.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() "
               "RATIONAL_B_SPLINE_CURVE(" + step_list(weights) + ") REPRESENTATION_ITEM(" +
               label + "))");
}

int step_bspline_surface(StepFile& f, const NurbsSurface& s, double tolerance,
                         const std::string& name) {
  std::vector<std::string> rows, weight_rows;  // control_points_list[u][v]
  for (int i = 0; i < s.size_u(); ++i) {
    std::vector<std::string> row, wrow;
    for (int j = 0; j < s.size_v(); ++j) {
      row.push_back(step_ref(step_point(f, s.control_point(i, j))));
      wrow.push_back(step_real(s.weight(i, j)));
    }
    rows.push_back(step_list(row));
    weight_rows.push_back(step_list(wrow));
  }
  const auto [umult, uknots] = knot_lists(s.knots_u());
  const auto [vmult, vknots] = knot_lists(s.knots_v());
  const std::string head = std::to_string(s.degree_u()) + "," + std::to_string(s.degree_v()) +
                           "," + step_list(rows) + ",.UNSPECIFIED.," +
                           step_logical(is_closed_u(s, tolerance)) + "," +
                           step_logical(is_closed_v(s, tolerance)) + ",.U.";
  const std::string knots = umult + "," + vmult + "," + uknots + "," + vknots + ",.UNSPECIFIED.";
  const std::string label = step_string(name, "surface name");
  if (!s.is_rational())  // ISO 10303-42 b_spline_surface_with_knots
    return f.add("B_SPLINE_SURFACE_WITH_KNOTS(" + label + "," + head + "," + knots + ")");
  // ISO 10303-42 rational_b_spline_surface as a complex instance, supertypes alphabetical.
  return f.add("(BOUNDED_SURFACE() B_SPLINE_SURFACE(" + head + ") B_SPLINE_SURFACE_WITH_KNOTS(" +
               knots + ") GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(" +
               step_list(weight_rows) + ") REPRESENTATION_ITEM(" + label + ") SURFACE())");
}

}  // namespace polarform
