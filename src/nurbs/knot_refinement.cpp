#include "src/nurbs/knot_refinement.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_search.h"

namespace polarform {

namespace {

void check_refinement(const BSpline& c, const std::vector<double>& X) {
  const int p = c.degree();
  for (std::size_t j = 0; j < X.size(); ++j) {
    if (!(X[j] >= c.front() && X[j] <= c.back()))
      throw InputError("refine_knots: X[" + std::to_string(j) + "] = " + to_text(X[j]) +
                       " is outside the domain [" + to_text(c.front()) + ", " + to_text(c.back()) +
                       "]");
    if (j > 0 && X[j] < X[j - 1])
      throw InputError("refine_knots: X is not sorted at index " + std::to_string(j));
  }
  for (std::size_t j = 0; j < X.size();) {
    std::size_t e = j;
    while (e < X.size() && X[e] == X[j]) ++e;
    const int total = sorted_multiplicity(c.knots(), X[j]) + static_cast<int>(e - j);
    if (total > p)
      throw InputError("refine_knots: knot " + to_text(X[j]) + " would get multiplicity " +
                       std::to_string(total) + " > degree " + std::to_string(p));
    j = e;
  }
}

}  // namespace

// NURBS Book A5.4 (RefineKnotVectCurve).
BSpline refine_knots(const BSpline& c, const std::vector<double>& X) {
  check_refinement(c, X);
  if (X.empty()) return c;
  const int p = c.degree();
  const int n = c.size() - 1;  // the book's n: index of the last control point
  const int r = static_cast<int>(X.size()) - 1;
  const Knots& U = c.knots();
  const Eigen::MatrixXd& P = c.coefs();

  const int a = find_span(p, U, c.size(), X[0]);
  const int b = find_span(p, U, c.size(), X[r]) + 1;
  Knots Ub(U.size() + r + 1);
  Eigen::MatrixXd Q(c.dim(), c.size() + r + 1);
  Q.leftCols(a - p + 1) = P.leftCols(a - p + 1);
  Q.rightCols(n - b + 2) = P.rightCols(n - b + 2);
  std::copy(U.begin(), U.begin() + a + 1, Ub.begin());
  std::copy(U.begin() + b + p, U.end(), Ub.begin() + b + p + r + 1);

  int i = b + p - 1, k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[j] <= U[i] && i > a) {
      Q.col(k - p - 1) = P.col(i - p - 1);
      Ub[k] = U[i];
      --k;
      --i;
    }
    Q.col(k - p - 1) = Q.col(k - p);
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = Ub[k + l] - X[j];
      if (alfa == 0.0) {
        Q.col(ind - 1) = Q.col(ind);
      } else {
        alfa /= Ub[k + l] - U[i - p + l];
        Q.col(ind - 1) = alfa * Q.col(ind - 1) + (1.0 - alfa) * Q.col(ind);
      }
    }
    Ub[k] = X[j];
    --k;
  }
  return BSpline(p, std::move(Ub), std::move(Q));
}

BSplineSurface refine_knots_u(const BSplineSurface& s, const std::vector<double>& X) {
  return BSplineSurface::from_along_u(refine_knots(s.along_u(), X), s.degree_v(), s.knots_v(),
                                      s.dim());
}

BSplineSurface refine_knots_v(const BSplineSurface& s, const std::vector<double>& X) {
  return BSplineSurface::from_along_v(refine_knots(s.along_v(), X), s.degree_u(), s.knots_u(),
                                      s.dim());
}

}  // namespace polarform
