#include "designers/convert/measured_knot_removal.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "designers/convert/conversion_error.h"
#include "designers/convert/refined_maximum.h"
#include "src/nurbs/knot_removal.h"

namespace polarform {

namespace {

// Samples per distinct knot span of the changed range and refined local maxima: quick for the
// bulk of the removals, fine for the one copy at each C0 knot, which may use the whole tolerance.
struct Sampling {
  int per_span, refine;
};
constexpr Sampling kQuick{8, 1}, kFine{24, 4};
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// Max radial error of C against R over the distinct knots of [a, b].
double range_error(const NurbsCurve2d& C, const PolarFunction& R, double a, double b,
                   Sampling sampling) {
  std::vector<double> grid{a};
  for (const Breakpoint& k : breakpoints(C.knots()))
    if (k.value > a && k.value < b) grid.push_back(k.value);
  grid.push_back(b);
  return refined_maximum([&](double u) { return radial_error_at(C, R, u, u); }, grid,
                         sampling.per_span, sampling.refine)
      .value;
}

// The curve with `times` copies of u removed if its measured error on the changed range stays
// within `limit`.
std::optional<NurbsCurve2d> try_removal(const NurbsCurve2d& C, const PolarFunction& R, double u,
                                        int times, double limit, Sampling sampling) {
  const Knots& U = C.knots();
  const int p = C.degree(), s = multiplicity(U, u);
  // Removing `times` copies of the knot u_r (its last copy, multiplicity s) changes the control
  // points r − p − times + 1 .. r − s + times − 1 (NURBS Book A5.8), so C over their supports.
  const auto r = std::upper_bound(U.begin(), U.end(), u) - U.begin() - 1;
  const auto last = static_cast<std::ptrdiff_t>(U.size()) - 1;
  const double a = U[std::max<std::ptrdiff_t>(r - p - times + 1, 0)];
  const double b = U[std::min<std::ptrdiff_t>(r - s + times + p, last)];
  // A5.8 with an unbounded coefficient tolerance removes every copy asked for; the measurement
  // decides.
  NurbsCurve2d candidate(remove_knot(C.homogeneous(), u, times, kUnbounded).spline);
  if (range_error(candidate, R, a, b, sampling) > limit) return std::nullopt;
  return candidate;
}

}  // namespace

// NURBS Book A5.8, each removal verified by measurement: first one copy of every knot where C is
// only C0 (so that readers see one smooth curve), then as many copies of every knot as the
// measurement allows (bisection on the count).
MeasuredRemoval remove_knots_within(const NurbsCurve2d& C, const PolarFunction& R, double tol,
                                    const std::vector<double>& keep, double share) {
  MeasuredRemoval out{C, 0};
  std::vector<double> interior;
  for (const Breakpoint& k : breakpoints(C.knots()))
    if (k.value > C.front() && k.value < C.back() &&
        std::find(keep.begin(), keep.end(), k.value) == keep.end())
      interior.push_back(k.value);
  for (double u : interior)
    if (multiplicity(out.curve.knots(), u) >= C.degree())
      if (auto c = try_removal(out.curve, R, u, 1, tol, kFine))
        out.curve = std::move(*c), ++out.removed;
  for (double u : interior) {
    int lo = 0, hi = multiplicity(out.curve.knots(), u);
    std::optional<NurbsCurve2d> best;
    while (lo < hi) {
      const int mid = (lo + hi + 1) / 2;
      if (auto c = try_removal(out.curve, R, u, mid, share * tol, kQuick))
        lo = mid, best = std::move(c);
      else
        hi = mid - 1;
    }
    if (best) out.curve = std::move(*best), out.removed += lo;
  }
  return out;
}

}  // namespace polarform
