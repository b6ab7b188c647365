#include "src/nurbs/end_circle_contacts.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "src/nurbs/brent_minimum.h"

namespace polarform {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Why the band: a curve with curvature ≤ κ stays out of the open ball of radius 1/κ tangent to it
// at C(e) over an arc length π/κ from C(e) (Schur's comparison theorem: the chord is at least the
// circle's, and its angle with C′(e) at most the circle's), so g(t) ≥ 1/κ_max there: contacts
// near the end never limit the pipe before the local bound does. Near the end g(t) → 1/κ(e) as a
// 0/0 limit: the circle sits on the tube by construction, and |v⊥| is lost in rounding, so
// the end's neighbourhood is left out rather than evaluated.

// g(t) = |v|² / (2|v⊥|), the radius at which the end circle at C(e) reaches the tube around C(t);
// infinite when v⊥ is at rounding level (|v⊥| ≤ 1e-12 |v|: C(t) on the line of the end tangent).
double contact_radius(const Eigen::Vector3d& end, const Eigen::Vector3d& unit_tangent,
                      const Eigen::Vector3d& at) {
  const Eigen::Vector3d v = at - end;
  const double normal = (v - v.dot(unit_tangent) * unit_tangent).norm();
  return normal > 1e-12 * v.norm() ? v.squaredNorm() / (2.0 * normal) : kInf;
}

// The smallest interior local minimum of g on (lo, hi): sampled at the table nodes, refined by
// Brent between the neighbours of each sampled local minimum. Only an interior minimum t* is a
// contact with the pipe surface: there |E − C(t)| ≥ r = g(t*) for t near t*, so E − C(t*) ⊥ C′(t*)
// and E lies on the circle of the pipe at t*. A minimum at the other end only means that the end
// circle enters the ball around that end point, beyond the open end of the pipe: the surface is
// met later, at an interior foot or where the end circles cross (end–end) — or, in principle, by
// an end circle that dips into the other end's opening and then touches the tube from inside, a
// contact this search does not follow.
EndContact smallest_contact(const SpineTable& table, double e, double lo, double hi) {
  const NurbsCurve3d& spine = table.spine();
  const auto d = spine.derivatives(e, 1);
  const Eigen::Vector3d end = d[0], tangent = d[1].normalized();
  const auto g = [&](double t) { return contact_radius(end, tangent, spine.point(t)); };
  std::vector<double> t{lo};
  for (int i = 0; i < table.size(); ++i)
    if (table.t(i) > lo && table.t(i) < hi) t.push_back(table.t(i));
  t.push_back(hi);
  std::vector<double> v(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) v[i] = g(t[i]);
  EndContact best{kInf, e, e};
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    if (v[i] > v[i - 1] || v[i] > v[i + 1]) continue;
    const Minimum m = brent_minimum(g, t[i - 1], t[i + 1]);
    if (m.x > lo && m.x < hi && m.value < best.radius) best = {m.value, e, m.x};
  }
  return best;
}

}  // namespace

// Maekawa et al. 1998, end-circle-to-body mode, in the closed form above.
EndContact end_body_contact(const SpineTable& table, double separation) {
  const double length = table.length();
  if (!(separation < length)) return {kInf, table.spine().front(), table.spine().front()};
  const double front = table.spine().front(), back = table.spine().back();
  const EndContact a = smallest_contact(table, front, table.parameter_at(separation), back);
  const EndContact b =
      smallest_contact(table, back, front, table.parameter_at(length - separation));
  return b.radius < a.radius ? b : a;
}

// Maekawa et al. 1998, end-circle-to-end-circle mode, in the closed form above.
EndContact end_end_contact(const NurbsCurve3d& spine) {
  const auto a = spine.derivatives(spine.front(), 1), b = spine.derivatives(spine.back(), 1);
  const Eigen::Vector3d ab = b[0] - a[0];
  const double gap = ab.norm();
  if (gap == 0.0) return {0.0, spine.front(), spine.back()};  // the end circles coincide or cross
  // Rows: X − C(a) in the normal plane at a, in the one at b, and on the bisector plane.
  Eigen::Matrix3d m;
  m.row(0) = a[1].normalized().transpose();
  m.row(1) = b[1].normalized().transpose();
  m.row(2) = (ab / gap).transpose();
  const Eigen::Vector3d rhs(0.0, m.row(1).dot(ab), 0.5 * gap);
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix3d> cod;
  cod.setThreshold(1e-10);  // rank-deficient when S is a line (e.g. a circle-arc spine)
  cod.compute(m);
  const Eigen::Vector3d x = cod.solve(rhs);
  if (!((m * x - rhs).norm() <= 1e-9 * gap)) return {kInf, spine.front(), spine.back()};
  return {x.norm(), spine.front(), spine.back()};
}

}  // namespace polarform
