#include "designers/convert/degree_limited.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <stop_token>
#include <string>

#include "designers/convert/conversion_error.h"
#include "designers/convert/knot_placement.h"
#include "designers/convert/profile_fit.h"
#include "designers/convert/profile_table.h"
#include "designers/convert/refined_maximum.h"
#include "designers/convert/spline_space.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/knot_removal.h"
#include "src/task_pool.h"

namespace polarform {

namespace {

constexpr int kMaxSpans = 20000;
// The fits: 2p + 2 samples per span; the full-distance share 1e-5 lets the curve slide along the
// profile.
constexpr double kSlide = 1e-5;
// The table's span errors (2·(2p + 2) + 1 points per span) must meet kShare·tol; the final
// measurement against R (every local maximum refined) decides.
constexpr double kShare = 0.99;
constexpr int kInsertionRounds = 200;
constexpr double kMinSpan = 1e-9;  // share of the domain: the shortest span the insertion makes

std::vector<double> uniform_breaks(double a, double b, int spans) {
  std::vector<double> out;
  for (int i = 0; i <= spans; ++i) out.push_back(i == spans ? b : a + (b - a) * i / spans);
  return out;
}

Eigen::Vector2d profile_point(const PolarFunction& R, double psi) {
  return R(psi) * Eigen::Vector2d(std::cos(psi), std::sin(psi));
}

// The first parameter (on 8 + 1 points per span) where the curve's polar angle stops increasing,
// if any: a polar profile is star-shaped about the origin, so a fold or loop of the curve (which
// the radial error alone would not see) is a miss.
std::optional<double> fold(const NurbsCurve2d& C, const std::vector<double>& breaks) {
  double last = 0.0;
  bool first = true;
  for (std::size_t j = 0; j + 1 < breaks.size(); ++j)
    for (int k = first ? 0 : 1; k <= 8; ++k) {
      const double u = breaks[j] + (breaks[j + 1] - breaks[j]) * k / 8;
      const Eigen::Vector2d c = C(u);
      const double psi = polar_angle_near(c.x(), c.y(), u);
      if (!first && !(psi > last)) return u;
      last = psi, first = false;
    }
  return std::nullopt;
}

// The result, its error measured against R itself over every span (conversion_error.h),
// samples_per_span + 1 samples per span and every local maximum of the samples refined by golden
// section; `at` receives the parameter of the largest error (infinite at a fold).
LimitedCurve measure(const SplineSpace& s, const PolarFunction& R, const Eigen::MatrixXd& coefs,
                     double* at = nullptr) {
  LimitedCurve out{s.curve(coefs), 0, 0, 0};
  out.control_points = out.curve.size();
  if (const std::optional<double> u = fold(out.curve, s.breaks())) {
    out.max_radial_error = out.max_normal_error = std::numeric_limits<double>::infinity();
    if (at) *at = *u;
    return out;
  }
  const Maximum m = refined_maximum([&](double u) { return radial_error_at(out.curve, R, u, u); },
                                    s.breaks(), samples_per_span(s.degree()), 4 * s.spans());
  double psi = 0.0, d[2];
  radial_error_at(out.curve, R, m.at, m.at, &psi);
  psi = R.closed()
            ? R.start + std::remainder(psi - R.start - std::numbers::pi, 2 * std::numbers::pi) +
                  std::numbers::pi
            : std::clamp(psi, R.start, R.end);
  R.derivatives(psi, 1, d);
  out.max_radial_error = m.value;
  // A radial offset δ moves the point by δ·R/√(R² + R'²) along the normal of r = R(ψ) (the
  // factor, at most 1, taken first so that round-off cannot lift it past δ).
  out.max_normal_error = m.value * std::min(1.0, std::abs(d[0]) / std::hypot(d[0], d[1]));
  if (at) *at = m.at;
  return out;
}

// One fit on given breaks with its span errors measured on the table: at the fit's samples, and
// densely (2·per_span + 1 points per span, the samples among them) when those meet `accept` — a
// fit whose samples miss it misses it densely too.
struct Fit {
  SplineSpace space;
  Eigen::MatrixXd coefs;
  std::vector<double> errors;
  double max = 0.0;
};

// The shape every fit of one degree shares: how the curve ends, and its knots that are not
// simple.
struct Shape {
  Ends ends = Ends::clamped;
  Multiplicities multiple;
};

Shape shape_of(const SplineSpace& s) { return {s.ends(), s.multiplicities()}; }

Fit fit_on(std::vector<double> breaks, Shape shape, const ProfileTable& table, int degree,
           const ProfileFitOptions& options, double accept) {
  SplineSpace space(degree, shape.ends, std::move(breaks), shape.multiple);
  FittedProfile f = fit_profile(space, table, options);
  std::vector<double> errors = std::move(f.sample_errors);
  if (*std::max_element(errors.begin(), errors.end()) <= accept)
    errors = span_errors(space, f.coefs, table, 2 * options.per_span);
  const double max = *std::max_element(errors.begin(), errors.end());
  return {std::move(space), std::move(f.coefs), std::move(errors), max};
}

// The density's mass over each span: error^(1/(p+1)), with a floor of a tenth of the mean
// density so that no stretch is left without knots by an error that is small by chance.
std::vector<double> need(const Fit& f) {
  const int p = f.space.degree();
  const std::vector<double>& b = f.space.breaks();
  std::vector<double> mass;
  for (double e : f.errors) mass.push_back(std::pow(e, 1.0 / (p + 1)));
  double mean = std::accumulate(mass.begin(), mass.end(), 0.0) / (b.back() - b.front());
  if (!(mean > 0)) mean = 1.0;  // an exact fit: spans of equal length
  for (std::size_t j = 0; j < mass.size(); ++j)
    mass[j] = std::max(mass[j], 0.1 * mean * (b[j + 1] - b[j]));
  return mass;
}

// The lowest order k (1..4) of R's derivatives that jumps between their values at `left_at` (just
// before a point, by h) and at `right_at` (just after it), each taken back to the point along its
// Taylor series; 0 if none does. R gives derivatives up to the third: the fourth's values on either
// side are one-sided difference quotients of R‴ over δ and 2δ, combined (Richardson) so that the
// fifth derivative's share, δ·R⁽⁵⁾, cancels from their difference.
int jump_order(const PolarFunction& R, double left_at, double right_at, double h) {
  double left[4], right[4];
  R.derivatives(left_at, 3, left);
  R.derivatives(right_at, 3, right);
  double scale = 0.0;
  for (int i = 0; i <= 3; ++i) scale += std::abs(left[i]) + std::abs(right[i]);
  for (int k = 1; k <= 3; ++k) {
    const double l = left[k] + (k < 3 ? h * left[k + 1] : 0.0);
    const double r = right[k] - (k < 3 ? h * right[k + 1] : 0.0);
    if (std::abs(l - r) > 1e-6 * scale) return k;
  }
  const auto third = [&R](double at) {
    double d[4];
    R.derivatives(at, 3, d);
    return d[3];
  };
  const double delta = 1e3 * h;
  const double l1 = (left[3] - third(left_at - delta)) / delta,
               r1 = (third(right_at + delta) - right[3]) / delta;
  const double l2 = (left[3] - third(left_at - 2 * delta)) / (2 * delta),
               r2 = (third(right_at + 2 * delta) - right[3]) / (2 * delta);
  const double jump = 2 * (r1 - l1) - (r2 - l2);
  return std::abs(jump) > 1e-6 * (scale + std::abs(l1) + std::abs(r1)) ? 4 : 0;
}

// The multiplicity of a degree-p knot that leaves the spline C^(k−1) where R's k-th derivative
// jumps (k >= 1), as smooth as R there; simple where R is smooth (k = 0).
int multiplicity_for(int k, int p) { return k == 0 ? 1 : std::clamp(p - (k - 1), 1, p); }

// The orders of R's derivative jumps (jump_order), taken once for every degree: across a closed
// R's seam, and at each breakpoint where one jumps. There a knot lets the spline follow the jump;
// elsewhere (a breakpoint of a smooth R) the knots are placed by need only.
struct Jumps {
  int seam = 0;
  std::vector<std::pair<double, int>> interior;  // (breakpoint, order)
};

Jumps jumps_of(const PolarFunction& R) {
  Jumps out;
  const double h = 1e-9 * (R.end - R.start);
  if (R.closed()) out.seam = jump_order(R, R.end - h, R.start + h, h);
  for (double b : R.breakpoints) {
    if (!(b > R.start && b < R.end)) continue;
    if (const int k = jump_order(R, b - h, b + h, h); k > 0) out.interior.emplace_back(b, k);
  }
  return out;
}

// Interpolation at `points` parameters equally spaced in ψ (the spans' ends for open curves).
LimitedCurve interpolation(const PolarFunction& R, int degree, int points) {
  const bool periodic = R.closed();
  // Closed: as many control values as points. Open: points = spans + degree, samples spread so
  // that the Schoenberg–Whitney condition holds.
  const int spans = periodic ? points : points - degree;
  const SplineSpace s(degree, periodic ? Ends::periodic : Ends::clamped,
                      uniform_breaks(R.start, R.end, spans));
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs(points, 2);
  for (int i = 0; i < points; ++i) {
    // Even degrees interpolate at span middles, where the periodic system is not singular.
    const double shift = degree % 2 == 0 ? 0.5 : 0.0;
    const double t = periodic ? R.start + (R.end - R.start) * (i + shift) / points
                              : R.start + (R.end - R.start) * i / (points - 1);
    double N[kMaxDegree + 1];
    const int first = s.basis(t, N);
    for (int j = 0; j <= degree; ++j) triplets.emplace_back(i, s.value(first + j), N[j]);
    rhs.row(i) = profile_point(R, t).transpose();
  }
  Eigen::SparseMatrix<double> A(points, s.size());
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw NumericalError("interpolation: singular system");
  return measure(s, R, solver.solve(rhs).transpose());
}

// The fits of steps 2-4: 2p + 2 samples per span, Lawson's steps toward the minimax.
ProfileFitOptions minimax_options(int p, const LimitedEffort& effort) {
  return {2 * p + 2, kSlide, effort.lawson_steps};
}

// The samples per span of the fits that predict and try (p + 5 rather than 2p + 2 from degree 4
// on): for the trials (bisection and removals) with 20 removal tries, the same 1418 and 1971
// control points on the 66 peer_counts rows as 2p + 2, p + 4 gave 1422 and 1983; for the
// placements' minimax fits, the same 1419 and 1971 with 8 tries.
int trial_samples(int p) { return std::min(2 * p + 2, p + 5); }

// A placement's minimax fit, whose error predicts the control points.
ProfileFitOptions predicting_options(int p, const LimitedEffort& effort) {
  ProfileFitOptions out = minimax_options(p, effort);
  out.per_span = trial_samples(p);
  return out;
}

// A refit whose error is within kNearMiss of the target: Lawson's steps to about convergence (the
// minimax gains a few per cent after the effort's steps; 40 take the hemispherical head's single
// sextic from 1.022 to 0.938 µm, against 0.99 needed at 1 µm).
constexpr double kNearMiss = 1.15;
ProfileFitOptions converged_options(int p) { return {2 * p + 2, kSlide, 40}; }

void throw_if_stopped(const std::stop_token& stop) {
  if (stop.stop_requested()) throw NumericalError("degree-limited profile: stopped");
}

// Step 1 of approximate_polar_curve: the density of need for degree p (its breaks and the mass
// over each span), the spans it asks for, the breaks every fit keeps, and the minimax fit on those
// spans with the control points it predicts.
struct Placement {
  int degree = 0;
  Shape shape;
  std::vector<double> fixed, breaks, mass;
  int spans = 0, fewest = 0;
  std::optional<Fit> minimax;
  // Of the clamped curve, if the minimax error scales like h^(p+1): the plain fits that placed
  // the knots miss the minimax fit's gain, which differs from degree to degree.
  double predicted_control_points = 0.0;
};

Placement place_knots(const PolarFunction& R, Ends ends, const Jumps& jumps,
                      const ProfileTable& table, int p, double tol, const LimitedEffort& effort,
                      const std::stop_token& stop) {
  Placement out;
  out.degree = p;
  out.shape.ends = ends;
  // A closed R's seam knot as smooth as R there (a cam whose first segment starts a rise at 0°
  // has a jump in R‴ or R″): the clamped curve has p + spans control points whatever the seam's
  // multiplicity, and the constraints it sheds free the fit.
  if (ends == Ends::periodic) out.shape.multiple.seam = multiplicity_for(jumps.seam, p);
  out.fixed = {R.start};
  for (const auto& [b, k] : jumps.interior)
    if (k <= p) {  // a jump of order k <= p: the spline can follow it
      out.fixed.push_back(b);
      out.shape.multiple.interior.emplace_back(b, multiplicity_for(k, p));
    }
  out.fixed.push_back(R.end);
  const Shape& shape = out.shape;
  // The knots' multiplicities beyond one: control points that do not come with spans.
  int extra = 0;
  for (const auto& [b, m] : shape.multiple.interior) extra += m - 1;
  // A periodic space needs p + 1 control values: p + 2 − seam − extra spans.
  out.fewest = std::max<int>(ends == Ends::periodic ? p + 2 - shape.multiple.seam - extra : 1,
                             static_cast<int>(out.fixed.size()) - 1);

  const ProfileFitOptions plain{2 * p + 2, kSlide, 0};
  // Knots by need: fits on breaks that equidistribute the last fit's measured error, sized for
  // the error of every span to meet kShare·tol if the error scales like h^(p+1).
  std::vector<double> breaks = uniform_breaks(R.start, R.end, std::max(16, 2 * out.fewest));
  std::vector<double> mass;
  for (std::size_t j = 0; j + 1 < breaks.size(); ++j) mass.push_back(breaks[j + 1] - breaks[j]);
  // The rounds need each span's error roughly (its (p+1)-th root): the samples' suffice.
  constexpr double kSamplesOnly = -1.0;
  Fit f = fit_on(equidistribute(breaks, mass, static_cast<int>(mass.size()), out.fixed), shape,
                 table, p, plain, kSamplesOnly);
  // The rounds wander rather than converge (the spans a round asks for rise and fall by a few),
  // so the round whose spans, scaled as if its error went like h^(p+1), are the fewest is kept.
  const auto asks = [&](const Fit& g) {
    return g.space.spans() * std::pow(g.max / (kShare * tol), 1.0 / (p + 1));
  };
  Fit kept = f;
  for (int round = 0; round < effort.placement_rounds; ++round) {
    throw_if_stopped(stop);
    mass = need(f);
    const double total = std::accumulate(mass.begin(), mass.end(), 0.0);
    const double n = std::ceil(total / std::pow(kShare * tol, 1.0 / (p + 1)));
    f = fit_on(
        equidistribute(f.space.breaks(), mass,
                       std::clamp<int>(static_cast<int>(std::min(n, 1e9)), out.fewest, kMaxSpans),
                       out.fixed),
        shape, table, p, plain, kSamplesOnly);
    if (asks(f) < asks(kept)) kept = f;
    if (n >= kMaxSpans) break;  // the span budget decides (step 2)
  }
  // The kept round's span errors measured densely: they size and place every later fit.
  f = std::move(kept);
  f.errors = span_errors(f.space, f.coefs, table, 2 * plain.per_span);
  mass = need(f);
  out.breaks = f.space.breaks();
  out.mass = std::move(mass);
  out.spans = f.space.spans();
  throw_if_stopped(stop);
  out.minimax = fit_on(equidistribute(out.breaks, out.mass, out.spans, out.fixed), shape, table, p,
                       predicting_options(p, effort), kShare * tol);
  const double spans = std::max<double>(
      out.fewest, out.spans * std::pow(out.minimax->max / (kShare * tol), 1.0 / (p + 1)));
  // A mirrored curve has the mirror images of the spans too, but for the one across the line.
  out.predicted_control_points =
      p + (ends == Ends::mirrored ? 2 * (spans + extra) - 1 : spans + extra);
  return out;
}

// The polynomial B-spline of a curve whose weights are all 1 (the fits' curves).
BSpline plain_spline(const NurbsCurve2d& C) {
  const BSpline& h = C.homogeneous();
  return BSpline(h.degree(), h.knots(), h.coefs().topRows(2));
}

// Steps 2-4 of approximate_polar_curve on the placement of step 1.
LimitedCurve fit_by_need(const PolarFunction& R, const ProfileTable& table, const Placement& place,
                         double tol, const LimitedEffort& effort, const std::stop_token& stop) {
  const int p = place.degree, fewest = place.fewest;
  const std::vector<double>& fixed = place.fixed;
  const ProfileFitOptions minimax = minimax_options(p, effort);
  // The fits that are kept only if they meet the tolerance: no Lawson steps spent on a hopeless
  // one,
  ProfileFitOptions trial = minimax;
  trial.target = kShare * tol;
  // and on fewer samples (trial_samples).
  trial.per_span = trial_samples(p);
  const auto fail = [&] {
    return NumericalError("degree-limited profile: no degree-" + std::to_string(p) +
                          " spline with up to " + std::to_string(kMaxSpans) + " spans meets " +
                          number_text(tol) + " mm");
  };

  // 2. The fewest spans on that density whose minimax fit meets the tolerance: grown until one
  // does, then bisected.
  const auto try_spans = [&](int n) {
    throw_if_stopped(stop);
    return fit_on(equidistribute(place.breaks, place.mass, n, fixed), place.shape, table, p, trial,
                  kShare * tol);
  };
  int hi = place.spans;
  Fit best = *place.minimax;  // try_spans(hi)
  while (best.max > kShare * tol) {
    if (hi >= kMaxSpans) throw fail();
    hi = std::min(kMaxSpans, std::max(hi + 1, static_cast<int>(std::ceil(hi * 1.1))));
    best = try_spans(hi);
  }
  int lo = std::max(fewest, static_cast<int>(0.7 * hi)) - 1;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    Fit c = try_spans(mid);
    if (c.max <= kShare * tol)
      hi = mid, best = std::move(c);
    else
      lo = mid;
  }

  // 3. Knot removal by refit: a mirrored curve's knot on the mirror line first (one control point
  // for one fit, with Lawson's steps until they no longer gain when it misses by a little), then
  // the interior breaks in the order of their removal bound on the current fit (Farin's
  // least-squares removal, knot_removal.h: how far the curve moves without the knot, the least
  // first), each removal kept when the refit still meets the tolerance. A bound beyond
  // 2^(p+4)·tol ends them: tried in the earlier order (smallest neighbouring span error first) on
  // the 66 peer_counts rows, such removals met the tolerance in 9 of 525 tries. The trial fits
  // give up their Lawson steps early when they are far off (ProfileFitOptions::target).
  // Removal tries begun beside others and no longer wanted (below): waited for only on leaving,
  // by when they are long done.
  std::vector<Task<std::optional<Fit>>> abandoned;
  if (place.shape.ends == Ends::mirrored) {
    const Shape smooth{Ends::mirrored_smooth, place.shape.multiple};
    Fit c = fit_on(best.space.breaks(), smooth, table, p, trial, kShare * tol);
    if (c.max > kShare * tol && c.max <= kNearMiss * kShare * tol)
      c = fit_on(best.space.breaks(), smooth, table, p, converged_options(p), kShare * tol);
    if (c.max <= kShare * tol) best = std::move(c);
  }
  {
    // (break, its removal bound on the current best), the bounds taken again after a success.
    std::vector<std::pair<double, double>> untried;
    const std::vector<double>& b = best.space.breaks();
    for (std::size_t i = 1; i + 1 < b.size(); ++i)
      if (!std::binary_search(fixed.begin(), fixed.end(), b[i])) untried.emplace_back(b[i], 0.0);
    const auto take_bounds = [&] {
      const BSpline xy = plain_spline(best.space.curve(best.coefs));
      for (auto& [at, bound] : untried) bound = remove_knot_least_squares(xy, at).bound;
    };
    take_bounds();
    const double hopeless = std::ldexp(kShare * tol, p + 4);
    // The untried break of the least bound, unless that is beyond hopeless; and one taken.
    const auto least = [&]() -> std::optional<double> {
      const auto l = std::min_element(untried.begin(), untried.end(),
                                      [](auto& x, auto& y) { return x.second < y.second; });
      if (l == untried.end() || !(l->second <= hopeless)) return std::nullopt;
      return l->first;
    };
    const auto take = [&](double at) {
      untried.erase(
          std::find_if(untried.begin(), untried.end(), [at](auto& u) { return u.first == at; }));
    };
    // Best's breaks without `at`.
    const auto without = [&](double at) {
      std::vector<double> fewer = best.space.breaks();
      fewer.erase(std::find(fewer.begin(), fewer.end(), at));
      return fewer;
    };
    const auto accept = [&](Fit& c) {
      if (!(c.max <= kShare * tol)) return false;
      best = std::move(c), take_bounds();
      return true;
    };
    for (std::size_t tries = 0; tries < effort.removal_tries; ++tries) {
      throw_if_stopped(stop);
      if (best.space.spans() - 1 < fewest) break;
      const std::optional<double> at = least();
      if (!at) break;
      take(*at);
      // The try after this one (the next least bound, as if this one fails) runs beside it, a
      // task with inputs of its own, and counts only if this one fails: the same tries in the
      // same order as one at a time. Abandoned when this one succeeds (skipped if not started).
      const auto wanted = std::make_shared<std::atomic<bool>>(true);
      std::optional<std::pair<double, Task<std::optional<Fit>>>> next;
      if (const auto n = least(); n && tries + 1 < effort.removal_tries)
        next.emplace(*n, run_task([fewer = without(*n), shape = shape_of(best.space), wanted,
                                   &table, p, trial, tol]() -> std::optional<Fit> {
          if (!*wanted) return std::nullopt;
          return fit_on(fewer, shape, table, p, trial, kShare * tol);
        }));
      Fit c = fit_on(without(*at), shape_of(best.space), table, p, trial, kShare * tol);
      if (accept(c)) {
        if (next) *wanted = false, abandoned.push_back(std::move(next->second));
      } else if (next) {
        ++tries;
        take(next->first);
        Fit d = *next->second.get();
        accept(d);
      }
    }
  }

  // 4. Verified against R itself (or its table); where it misses, the span of the largest error
  // is split (greedy insertion) and the minimax fit repeated.
  PolarFunction tabled = R;
  if (effort.verify_on_table)
    tabled.derivatives = [&table](double psi, int d, double* out) {
      double v[2];  // the table's R and R' (measure asks for d <= 1)
      table.derivatives(psi, v);
      for (int k = 0; k <= std::min(d, 1); ++k) out[k] = v[k];
    };
  for (int round = 0;; ++round) {
    throw_if_stopped(stop);
    double at = 0.0;
    LimitedCurve out = measure(best.space, tabled, best.coefs, &at);
    if (out.max_radial_error <= tol) return out;
    if (round >= kInsertionRounds || best.space.spans() >= kMaxSpans) throw fail();
    std::vector<double> b = best.space.breaks();
    const std::size_t j =
        std::clamp<std::size_t>(
            static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), at) - b.begin()), 1,
            b.size() - 1) -
        1;
    // A miss that splitting cannot reach (a fold the fit keeps) ends before round-off does.
    if (!(b[j + 1] - b[j] > kMinSpan * (R.end - R.start))) throw fail();
    b.insert(b.begin() + static_cast<std::ptrdiff_t>(j) + 1, 0.5 * (b[j] + b[j + 1]));
    best = fit_on(std::move(b), shape_of(best.space), table, p, minimax, kShare * tol);
  }
}

void check_degree_and_tolerance(int degree, double tol) {
  if (degree < 1 || degree > kMaxDegree)
    throw InputError("degree-limited profile: degree " + std::to_string(degree) + " outside [1, " +
                     std::to_string(kMaxDegree) + "]");
  if (!(tol > 0)) throw InputError("degree-limited profile: tolerance must be > 0 mm");
}

}  // namespace

LimitedCurve approximate_polar_curve(const PolarFunction& R, int degree, double tol,
                                     const LimitedEffort& effort) {
  check_degree_and_tolerance(degree, tol);
  if (mirror_symmetric(R, tol)) {
    PolarFunction half = R;
    half.end = 0.5 * (R.start + R.end);
    half.breakpoints.erase(
        std::lower_bound(half.breakpoints.begin(), half.breakpoints.end(), half.end),
        half.breakpoints.end());
    return fewest_control_points(half, {degree}, tol, effort, {}, Mirror::at_end);
  }
  const ProfileTable table(R, effort.table_intervals);
  const Ends ends = R.closed() ? Ends::periodic : Ends::clamped;
  return fit_by_need(R, table, place_knots(R, ends, jumps_of(R), table, degree, tol, effort, {}),
                     tol, effort, {});
}

LimitedCurve fewest_control_points(const PolarFunction& R, const std::vector<int>& degrees,
                                   double tol, const LimitedEffort& effort, std::stop_token stop,
                                   Mirror mirror) {
  if (degrees.empty()) throw InputError("degree-limited profile: no degree to try");
  for (int degree : degrees) check_degree_and_tolerance(degree, tol);
  if (mirror == Mirror::at_end && R.closed())
    throw InputError("degree-limited profile: a closed profile has no mirror line at its end");
  const ProfileTable table(R, effort.table_intervals);
  const Ends ends = R.closed()                 ? Ends::periodic
                    : mirror == Mirror::at_end ? Ends::mirrored
                                               : Ends::clamped;
  // Every degree's knots placed (plain fits, cheap), each a task of its own: the highest degree,
  // the costliest, first, so that the cores finish together.
  std::vector<int> by_cost = degrees;
  std::sort(by_cost.begin(), by_cost.end(), std::greater<>());
  const Jumps jumps = jumps_of(R);
  std::vector<Task<Placement>> placing;
  for (int degree : by_cost)
    placing.push_back(run_task(
        [&, degree] { return place_knots(R, ends, jumps, table, degree, tol, effort, stop); }));
  std::vector<Placement> places;
  for (Task<Placement>& f : placing) places.push_back(f.get());
  std::stable_sort(places.begin(), places.end(), [](const Placement& a, const Placement& b) {
    return a.predicted_control_points < b.predicted_control_points ||
           (a.predicted_control_points == b.predicted_control_points && a.degree < b.degree);
  });
  // Then the minimax fits in the order of the control points the placements predict, as many at
  // a time (each a task of its own) as are still wanted, until `finalists` have met the tolerance,
  // then one at a time while the next predicts fewer control points than the best result (the
  // predictions err by a few control points, which decides between degrees on small curves: a
  // head's single sextic).
  std::optional<LimitedCurve> best;
  std::optional<NumericalError> failure;
  std::size_t fitted = 0, next = 0;
  const auto promising = [&](std::size_t k) {
    return best && places[k].predicted_control_points < best->control_points;
  };
  while (next < places.size() && (fitted < effort.finalists || promising(next))) {
    std::vector<Task<LimitedCurve>> fitting;
    const std::size_t batch = fitted < effort.finalists ? effort.finalists - fitted : 1;
    for (std::size_t k = next; k < std::min(places.size(), next + batch); ++k)
      fitting.push_back(
          run_task([&, k] { return fit_by_need(R, table, places[k], tol, effort, stop); }));
    next += fitting.size();
    for (Task<LimitedCurve>& f : fitting) try {
        LimitedCurve c = f.get();
        ++fitted;
        if (!best || c.control_points < best->control_points ||
            (c.control_points == best->control_points && c.curve.degree() < best->curve.degree()))
          best = std::move(c);
      } catch (const NumericalError& e) {
        failure = e;
      }
  }
  if (!best) throw *failure;
  return std::move(*best);
}

LimitedCurve interpolate_polar_curve(const PolarFunction& R, int degree, double tol) {
  if (!(tol > 0)) throw InputError("interpolation: tolerance must be > 0 mm");
  const int fewest = R.closed() ? degree + 1 : degree + 2;
  // Double until the tolerance is met, then bisect for the fewest points.
  int lo = fewest, hi = fewest;
  LimitedCurve best = interpolation(R, degree, hi);
  while (best.max_radial_error > tol) {
    lo = hi;
    hi *= 2;
    if (hi > kMaxSpans)
      throw NumericalError("interpolation: " + std::to_string(kMaxSpans) +
                           " points do not meet " + number_text(tol) + " mm");
    best = interpolation(R, degree, hi);
  }
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    LimitedCurve c = interpolation(R, degree, mid);
    if (c.max_radial_error <= tol)
      hi = mid, best = std::move(c);
    else
      lo = mid;
  }
  return best;
}

}  // namespace polarform
