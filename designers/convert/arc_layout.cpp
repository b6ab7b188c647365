#include "designers/convert/arc_layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {

namespace {

// An arc may give up this share of its length to end on a knot of F.
constexpr double kSnapShare = 0.6;

}  // namespace

double max_arc_sweep(ArcKind kind) {
  return kind == ArcKind::quartic ? std::numbers::pi : 2 * std::numbers::pi / 3;
}

double arc_synchronization_error(const BSplineFunction& F, double a, double b, ArcKind kind,
                                 AlphaRule alpha, int samples) {
  const double phi = 0.5 * (b - a);
  const double al = kind == ArcKind::quartic ? quartic_alpha(phi, alpha) : 1.0;
  double worst = 0.0;
  for (int k = 1; k <= samples; ++k) {
    const double eta = static_cast<double>(k) / (samples + 1);
    const double xi = kind == ArcKind::quartic ? quartic_arc_angle(phi, al, eta)
                                               : rqb_arc_angle(phi, eta);
    worst = std::max(worst, std::abs(F(a + xi) - F(a + 2 * phi * eta)));
  }
  return worst;
}

std::vector<double> layout_arcs(const BSplineFunction& F, const std::vector<double>& forced,
                                const ArcLayoutOptions& options) {
  if (!(options.tolerance > 0)) throw InputError("arc layout: tolerance must be > 0");
  std::vector<double> stops{F.front()};
  for (double t : forced)
    if (t > stops.back() && t < F.back()) stops.push_back(t);
  stops.push_back(F.back());

  const double max_sweep = max_arc_sweep(options.kind);
  std::vector<double> knots;  // F's distinct interior knots
  for (const Breakpoint& k : breakpoints(F.knots()))
    if (k.value > F.front() && k.value < F.back()) knots.push_back(k.value);
  auto fits = [&](double a, double b) {
    return arc_synchronization_error(F, a, b, options.kind, options.alpha) <= options.tolerance;
  };
  std::vector<double> breaks{stops.front()};
  for (std::size_t s = 0; s + 1 < stops.size(); ++s) {
    const double end = stops[s + 1];
    double a = stops[s];
    while (a < end) {
      double b = std::min(end, a + max_sweep);
      if (!fits(a, b)) {
        // Bisection for the longest arc that fits; the sampled error grows with the sweep.
        double lo = a, hi = b;
        while (hi - lo > 1e-4 * (b - a)) {
          const double mid = 0.5 * (lo + hi);
          (fits(a, mid) ? lo : hi) = mid;
        }
        b = lo;
        if (b <= a) throw NumericalError("arc layout: no arc meets the tolerance");
      }
      // Avoid a sliver at the end of a stretch: share the last two arcs evenly.
      if (b < end && end - b < 0.25 * (b - a)) b = 0.5 * (a + end);
      // End the arc on F's last interior knot in its final stretch when there is one: at an arc
      // junction the product is only C¹ anyway, so that knot then adds no control points.
      if (b < end) {
        const auto after = std::upper_bound(knots.begin(), knots.end(), b);
        if (after != knots.begin() && *(after - 1) > a + kSnapShare * (b - a)) b = *(after - 1);
      }
      breaks.push_back(b);
      a = b;
    }
  }
  return breaks;
}

}  // namespace polarform
