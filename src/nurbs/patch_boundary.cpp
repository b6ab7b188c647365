// Ordering, orienting and snapping the four boundary curves of a patch (Piegl & Tiller 2001, §2;
// spec P1: corners matched by end points, wrong-way curves reversed, domains normalised to [0, 1]).
#include "src/nurbs/patch_boundary.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

// The clamped curve on [0, 1] by the affine map t -> (t − a)/(b − a) of its knots.
NurbsCurve3d normalised(const NurbsCurve3d& c) {
  const BSpline h = clip(c.homogeneous(), c.front(), c.back());
  Knots U = h.knots();
  const double a = h.front(), b = h.back();
  for (double& t : U) t = (t - a) / (b - a);
  for (int i = 0; i <= h.degree(); ++i) {  // exact ends, whatever the rounding of the map
    U[i] = 0.0;
    U[U.size() - 1 - i] = 1.0;
  }
  return NurbsCurve3d(BSpline(h.degree(), std::move(U), h.coefs()));
}

// c with its first (at_start) or last control point moved to p (non-rational, clamped).
NurbsCurve3d with_end(const NurbsCurve3d& c, bool at_start, const Eigen::Vector3d& p) {
  Eigen::MatrixXd P = c.homogeneous().coefs();
  P.col(at_start ? 0 : P.cols() - 1) << p, 1.0;
  return NurbsCurve3d(BSpline(c.degree(), c.knots(), std::move(P)));
}

}  // namespace

// NURBS Book §6.1 (reversal): knots t_i -> a + b − t_{m−i}, control points in reverse order.

// Piegl & Tiller 2001, §2: the loop c0 (v = 0), c1 (u = 1), c2 (v = 1, backwards), c3 (u = 0,
// backwards).
PatchBoundary boundary_from_loop(const std::array<NurbsCurve3d, 4>& loop, double corner_tolerance) {
  std::array<NurbsCurve3d, 4> c;
  for (int k = 0; k < 4; ++k) {
    if (loop[k].is_rational())
      throw InputError("patch boundary: curve " + std::to_string(k) +
                       " is rational; expected a non-rational B-spline");
    c[k] = normalised(loop[k]);
    const double w = c[k].weight(0);  // a constant weight is no rationality: divide it out
    if (w != 1.0)
      c[k] = NurbsCurve3d(BSpline(c[k].degree(), c[k].knots(), c[k].homogeneous().coefs() / w));
  }
  const auto start = [&](int k) { return c[k].point(0.0); };
  const auto end = [&](int k) { return c[k].point(1.0); };
  // c0 runs towards whichever end of c1 is nearer to one of its own ends.
  const auto gap_to_c1 = [&](const Eigen::Vector3d& p) {
    return std::min((p - start(1)).norm(), (p - end(1)).norm());
  };
  if (gap_to_c1(start(0)) < gap_to_c1(end(0))) c[0] = reversed(c[0]);
  for (int k = 1; k < 4; ++k)
    if ((end(k) - end(k - 1)).norm() < (start(k) - end(k - 1)).norm()) c[k] = reversed(c[k]);
  for (int k = 0; k < 4; ++k) {  // corner k: where c_k starts and c_{k−1} ends
    const int prev = (k + 3) % 4;
    const double gap = (start(k) - end(prev)).norm();
    if (!(gap <= corner_tolerance))
      throw InputError("patch boundary: corner " + std::to_string(k) + " (start of curve " +
                       std::to_string(k) + ", end of curve " + std::to_string(prev) +
                       ") has a gap of " + to_text(gap) + " mm, above the corner tolerance " +
                       to_text(corner_tolerance) + " mm");
  }
  std::array<Eigen::Vector3d, 4> corner;
  for (int k = 0; k < 4; ++k) corner[k] = 0.5 * (start(k) + end((k + 3) % 4));
  for (int k = 0; k < 4; ++k)
    c[k] = with_end(with_end(c[k], true, corner[k]), false, corner[(k + 1) % 4]);
  return PatchBoundary{c[0], reversed(c[2]), reversed(c[3]), c[1]};
}

}  // namespace polarform
