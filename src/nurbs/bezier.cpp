#include "src/nurbs/bezier.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_refinement.h"
#include "src/nurbs/knot_search.h"

namespace polarform {

namespace {

void check_breaks(const BSpline& c, const std::vector<double>& breaks) {
  if (breaks.size() < 2 || breaks.front() != c.front() || breaks.back() != c.back())
    throw InputError("bezier_stack: breaks must run from the domain start " + to_text(c.front()) +
                     " to its end " + to_text(c.back()));
  for (std::size_t i = 1; i < breaks.size(); ++i)
    if (!(breaks[i] > breaks[i - 1]))
      throw InputError("bezier_stack: breaks not strictly increasing at index " +
                       std::to_string(i));
  for (const Breakpoint& b : breakpoints(c.knots()))
    if (b.value > c.front() && b.value < c.back() &&
        !std::binary_search(breaks.begin(), breaks.end(), b.value))
      throw InputError("bezier_stack: interior knot " + to_text(b.value) + " is not a break");
}

std::vector<double> domain_breaks(const BSpline& c) {
  std::vector<double> out;
  for (const Breakpoint& b : breakpoints(c.knots()))
    if (b.value >= c.front() && b.value <= c.back()) out.push_back(b.value);
  return out;
}

}  // namespace

// NURBS Book A5.6, done as one knot refinement (A5.4) to multiplicity p at every break.
Eigen::MatrixXd bezier_stack(const BSpline& c, const std::vector<double>& breaks) {
  check_breaks(c, breaks);
  const int p = c.degree(), nseg = static_cast<int>(breaks.size()) - 1;
  const Knots& U = c.knots();
  Eigen::MatrixXd S(c.dim(), nseg * (p + 1));
  if (p == 0) {
    for (int i = 0; i < nseg; ++i) S.col(i) = c.coefs().col(find_span(0, U, c.size(), breaks[i]));
    return S;
  }
  std::vector<double> X;
  for (double b : breaks) X.insert(X.end(), std::max(0, p - sorted_multiplicity(U, b)), b);
  const BSpline r = refine_knots(c, X);
  const Knots& R = r.knots();
  auto it = R.begin();
  for (int i = 0; i < nseg; ++i) {
    it = std::upper_bound(it, R.end(), breaks[i]);
    const int last = static_cast<int>(it - R.begin()) - 1;  // span [breaks[i], breaks[i+1])
    S.middleCols(i * (p + 1), p + 1) = r.coefs().middleCols(last - p, p + 1);
  }
  return S;
}

Eigen::MatrixXd bezier_stack(const BSplineSurface& s, const std::vector<double>& ubreaks,
                             const std::vector<double>& vbreaks) {
  const int d = s.dim(), nv = s.size_v();
  const Eigen::MatrixXd Su = bezier_stack(s.along_u(), ubreaks);  // row j·d + k, column I
  const Eigen::Index NI = Su.cols();
  Eigen::MatrixXd M(d * NI, nv);  // row I·d + k, column j: the v-direction view
  for (Eigen::Index I = 0; I < NI; ++I)
    for (int j = 0; j < nv; ++j) M.block(I * d, j, d, 1) = Su.block(j * d, I, d, 1);
  return bezier_stack(BSpline(s.degree_v(), s.knots_v(), std::move(M)), vbreaks);
}

BezierSegments decompose_bezier(const BSpline& c) {
  BezierSegments out{c.degree(), domain_breaks(c), {}};
  const Eigen::MatrixXd S = bezier_stack(c, out.breaks);
  const int w = c.degree() + 1;
  for (Eigen::Index i = 0; i < S.cols(); i += w) out.segments.emplace_back(S.middleCols(i, w));
  return out;
}

// Bae 2002, eq. (A.8): the full-multiplicity knot vector of the pieces.
BSpline compose_bezier(const BezierSegments& bezier) {
  const int p = bezier.degree, nseg = static_cast<int>(bezier.segments.size());
  if (p < 0 || p > kMaxDegree)
    throw InputError("compose_bezier: degree " + std::to_string(p) + " outside [0, " +
                     std::to_string(kMaxDegree) + "]");
  if (nseg < 1 || static_cast<int>(bezier.breaks.size()) != nseg + 1)
    throw InputError("compose_bezier: " + std::to_string(bezier.breaks.size()) + " breaks for " +
                     std::to_string(nseg) + " segments, expected segments + 1 >= 2");
  for (int i = 0; i < nseg; ++i)
    if (!(bezier.breaks[i + 1] > bezier.breaks[i]))
      throw InputError("compose_bezier: breaks not strictly increasing at index " +
                       std::to_string(i + 1));
  const Eigen::Index dim = bezier.segments[0].rows();
  for (int i = 0; i < nseg; ++i)
    if (bezier.segments[i].rows() != dim || bezier.segments[i].cols() != p + 1)
      throw InputError("compose_bezier: segment " + std::to_string(i) + " is " +
                       std::to_string(bezier.segments[i].rows()) + " x " +
                       std::to_string(bezier.segments[i].cols()) + ", expected " +
                       std::to_string(dim) + " x " + std::to_string(p + 1));
  // A break is shared (multiplicity p) when the pieces meet exactly; a degree-0 piece never shares.
  std::vector<bool> shared(nseg, false);
  int cols = nseg * (p + 1);
  for (int i = 1; i < nseg; ++i) {
    shared[i] = p > 0 && bezier.segments[i].col(0) == bezier.segments[i - 1].col(p);
    cols -= shared[i];
  }
  Knots U(p + 1, bezier.breaks.front());
  Eigen::MatrixXd P(dim, cols);
  int c = 0;
  for (int i = 0; i < nseg; ++i) {
    if (i > 0) U.insert(U.end(), shared[i] ? p : p + 1, bezier.breaks[i]);
    const int skip = shared[i] ? 1 : 0;
    P.middleCols(c, p + 1 - skip) = bezier.segments[i].rightCols(p + 1 - skip);
    c += p + 1 - skip;
  }
  U.insert(U.end(), p + 1, bezier.breaks.back());
  return BSpline(p, std::move(U), std::move(P));
}

}  // namespace polarform
