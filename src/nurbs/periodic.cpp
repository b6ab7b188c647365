#include "src/nurbs/periodic.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_search.h"

namespace polarform {

// Bae 2002, eq. (3.9).
Knots periodic_knots(int degree, const std::vector<double>& breaks) {
  const int k = static_cast<int>(breaks.size()) - 1;
  if (k < 1)
    throw InputError("periodic_knots: " + std::to_string(breaks.size()) +
                     " breaks, expected at least 2 (v_s and v_e)");
  for (int i = 1; i <= k; ++i)
    if (!(breaks[i] > breaks[i - 1]) || !std::isfinite(breaks[i]) || !std::isfinite(breaks[0]))
      throw InputError("periodic_knots: breaks not finite and strictly increasing at index " +
                       std::to_string(i));
  return periodic_knots(degree, std::vector<double>(breaks.begin(), breaks.end() - 1), breaks[k]);
}

Knots periodic_knots(int degree, const std::vector<double>& period_knots, double end) {
  if (degree < 0 || degree > kMaxDegree)
    throw InputError("periodic_knots: degree " + std::to_string(degree) + " outside [0, " +
                     std::to_string(kMaxDegree) + "]");
  const int K = static_cast<int>(period_knots.size());
  if (K < 1) throw InputError("periodic_knots: no knot in the period");
  int run = 1;
  for (int i = 0; i < K; ++i) {
    const double t = period_knots[static_cast<std::size_t>(i)];
    if (!std::isfinite(t) || !(t < end) || (i > 0 && !(t >= period_knots[i - 1])))
      throw InputError(
          "periodic_knots: period knots not finite, non-decreasing and below the end "
          "at index " +
          std::to_string(i));
    run = i > 0 && t == period_knots[i - 1] ? run + 1 : 1;
    if (run > std::max(1, degree))
      throw InputError("periodic_knots: knot " + to_text(t) + " repeated more than the degree");
  }
  if (!std::isfinite(end)) throw InputError("periodic_knots: the period's end is not finite");
  const double period = end - period_knots.front();
  Knots out;
  out.reserve(static_cast<std::size_t>(K + 2 * degree + 1));
  for (int i = -degree; i <= K + degree; ++i) {
    const int q = (i % K + K) % K;
    out.push_back(period_knots[static_cast<std::size_t>(q)] + period * ((i - q) / K));
  }
  return out;
}

// Bae 2002, eqs. (3.9)-(3.10).
BSpline periodic_bspline(int degree, const std::vector<double>& breaks,
                         const Eigen::MatrixXd& coefs) {
  Knots U = periodic_knots(degree, breaks);
  const int k = static_cast<int>(breaks.size()) - 1;
  if (coefs.cols() != k)
    throw InputError("periodic_bspline: " + std::to_string(coefs.cols()) +
                     " control values, expected one per span (" + std::to_string(k) + ")");
  Eigen::MatrixXd P(coefs.rows(), k + degree);
  for (int i = 0; i < k + degree; ++i) P.col(i) = coefs.col(i % k);
  return BSpline(degree, std::move(U), std::move(P));
}

// Bae 2002, §3.3.1 ("clipping"), by NURBS Book A5.1.
BSpline clip(const BSpline& c, double a, double b) {
  if (!(c.front() <= a && a < b && b <= c.back()))
    throw InputError("clip: [" + to_text(a) + ", " + to_text(b) +
                     "] is not a non-empty interval inside the domain [" + to_text(c.front()) +
                     ", " + to_text(c.back()) + "]");
  const int p = c.degree();
  BSpline r = insert_knot(c, a, std::max(0, p - sorted_multiplicity(c.knots(), a)));
  r = insert_knot(r, b, std::max(0, p - sorted_multiplicity(r.knots(), b)));
  const Knots& U = r.knots();
  // U[sa] = a < U[sa+1] starts the first span in [a, b]; U[eb - 1] < b = U[eb] ends the last.
  const int sa = static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;
  const int eb = static_cast<int>(std::lower_bound(U.begin(), U.end(), b) - U.begin());
  Knots K(p + 1, a);
  K.insert(K.end(), U.begin() + sa + 1, U.begin() + eb);
  K.insert(K.end(), p + 1, b);
  return BSpline(p, std::move(K), r.coefs().middleCols(sa - p, eb - sa + p));
}

BSplineSurface clip_u(const BSplineSurface& s, double a, double b) {
  return BSplineSurface::from_along_u(clip(s.along_u(), a, b), s.degree_v(), s.knots_v(), s.dim());
}

BSplineSurface clip_v(const BSplineSurface& s, double a, double b) {
  return BSplineSurface::from_along_v(clip(s.along_v(), a, b), s.degree_u(), s.knots_u(), s.dim());
}

}  // namespace polarform
