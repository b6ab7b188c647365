#include "src/nurbs/knot_insertion.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_search.h"

namespace polarform {

// NURBS Book A5.1 (CurveKnotIns).
BSpline insert_knot(const BSpline& c, double u, int times) {
  const int p = c.degree(), n = c.size();
  const Knots& U = c.knots();
  if (times < 0)
    throw InputError("insert_knot: times is " + std::to_string(times) + ", expected >= 0");
  if (!(u >= c.front() && u <= c.back()))
    throw InputError("insert_knot: u = " + to_text(u) + " is outside the domain [" +
                     to_text(c.front()) + ", " + to_text(c.back()) + "]");
  if (times == 0) return c;  // nothing to insert, whatever the multiplicity (clip at clamped ends)
  const int s = sorted_multiplicity(U, u);
  if (s + times > p)
    throw InputError("insert_knot: inserting u = " + to_text(u) + " " + std::to_string(times) +
                     " times would give multiplicity " + std::to_string(s + times) + " > degree " +
                     std::to_string(p));

  // U[k] <= u < U[k+1]; the knots equal to u (if any) are U[k-s+1..k].
  const int k = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  const int r = times;

  Knots UQ(U.size() + r);
  std::copy(U.begin(), U.begin() + k + 1, UQ.begin());
  std::fill(UQ.begin() + k + 1, UQ.begin() + k + 1 + r, u);
  std::copy(U.begin() + k + 1, U.end(), UQ.begin() + k + 1 + r);

  const Eigen::MatrixXd& P = c.coefs();
  Eigen::MatrixXd Q(c.dim(), n + r);
  Q.leftCols(k - p + 1) = P.leftCols(k - p + 1);
  Q.rightCols(n - (k - s)) = P.rightCols(n - (k - s));
  Eigen::MatrixXd R = P.middleCols(k - p, p - s + 1);
  int L = k - p;
  for (int j = 1; j <= r; ++j) {
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const double alpha = (u - U[L + i]) / (U[i + k + 1] - U[L + i]);
      R.col(i) = alpha * R.col(i + 1) + (1.0 - alpha) * R.col(i);
    }
    Q.col(L) = R.col(0);
    Q.col(k + r - j - s) = R.col(p - j - s);
  }
  for (int i = L + 1; i < k - s; ++i) Q.col(i) = R.col(i - L);
  return BSpline(p, std::move(UQ), std::move(Q));
}

BSplineSurface insert_knot_u(const BSplineSurface& s, double u, int times) {
  return BSplineSurface::from_along_u(insert_knot(s.along_u(), u, times), s.degree_v(), s.knots_v(),
                                      s.dim());
}

BSplineSurface insert_knot_v(const BSplineSurface& s, double v, int times) {
  return BSplineSurface::from_along_v(insert_knot(s.along_v(), v, times), s.degree_u(), s.knots_u(),
                                      s.dim());
}

}  // namespace polarform
