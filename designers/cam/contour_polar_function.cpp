#include "designers/cam/contour_polar_function.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "designers/cam/displacement_polar_function.h"
#include "designers/cam/extremum_search.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kTableSamples = 512;
// The highest derivative of R given (PolarFunction::derivatives).
constexpr int kMaxOrder = 3;

struct CurveTable {
  CamTrace trace;
  int direction;              // sign of dψ/dθ: -σ
  std::vector<double> theta;  // increasing, 0 .. 2π
  std::vector<double> psi;    // unwrapped ψ(θ), monotone in `direction`
  std::vector<int> segment;   // segment holding [theta[i], theta[i+1]]
  // dψ/dθ at both ends of [theta[i], theta[i+1]], taken inside its segment (for the Hermite start).
  std::vector<double> rate_lo, rate_hi;
};

// Curve point in the cam frame as jets of order d, θ in segment `seg`.
void curve_jets(const CurveTable& t, int seg, double theta, int d, Jet* xy) {
  Eigen::Vector2d p[4];
  t.trace.point(seg, theta, d, p);
  for (int c = 0; c < 2; ++c) {
    double v[4] = {};
    for (int k = 0; k <= d; ++k) v[k] = p[k](c);
    xy[c] = Jet::from(v, d);
  }
}

// dψ/dθ = (x y' - y x') / (x² + y²).
double psi_rate(const Jet* xy) {
  return (xy[0][0] * xy[1][1] - xy[1][0] * xy[0][1]) / (xy[0][0] * xy[0][0] + xy[1][0] * xy[1][0]);
}

[[noreturn]] void not_single_valued(double from, double to, const CamTrace& trace) {
  throw InputError("cam " + trace.what +
                   " is not single-valued in polar angle between θ = " + degrees_text(from) +
                   " and " + degrees_text(to) + " (undercut, cusp or loop); " + trace.remedy);
}

// The remedy depends on the follower: a roller's radius can be reduced, a flat face needs
// Rb + s + s'' > 0 (a larger base radius or a gentler acceleration), a knife edge a larger base.
std::string remedy(const PlateCam& cam, CamCurve curve) {
  const FollowerKind follower =
      curve == CamCurve::Contour ? cam.follower().kind : FollowerKind::KnifeEdge;
  return follower == FollowerKind::Roller ? "increase the base radius or reduce the roller radius"
         : follower == FollowerKind::FlatFaced ? "increase the base radius or lengthen the segment "
                                                 "(a flat face needs Rb + s + s'' > 0)"
                                               : "increase the base radius or lengthen the segment";
}

std::shared_ptr<CurveTable> build_table(CamTrace trace) {
  const int direction = -sense(trace.rotation);
  auto t =
      std::make_shared<CurveTable>(CurveTable{std::move(trace), direction, {}, {}, {}, {}, {}});
  const std::vector<MotionSegment>& segs = t->trace.program.segments();
  // Margin > 0 where ψ runs the right way.
  const auto margin = [&](int seg, double theta) {
    Jet xy[2];
    curve_jets(*t, seg, theta, 1, xy);
    return t->direction * psi_rate(xy);
  };
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    const double a = segs[s].start(), b = segs[s].end();
    const int n = std::max(8, static_cast<int>(std::ceil(kTableSamples * (b - a) / kTwoPi)));
    std::vector<double> thetas(n + 1), margins(n + 1), raw_psi(n + 1);
    for (int i = 0; i <= n; ++i) {
      thetas[i] = i == n ? b : a + (b - a) * i / n;
      Jet xy[2];
      curve_jets(*t, s, thetas[i], 1, xy);
      margins[i] = t->direction * psi_rate(xy);
      raw_psi[i] = std::atan2(xy[1][0], xy[0][0]);
    }
    for (int i = 0; i <= n; ++i) {
      double bad = margins[i] <= 0 ? thetas[i] : std::numeric_limits<double>::quiet_NaN();
      // A strict local minimum of the samples may hide a dip below zero: refine it. (Flat
      // stretches — dwells, where the contour is a circle — carry only rounding noise.)
      const double noise = 1e-9 * std::abs(margins[i]);
      if (std::isnan(bad) && i > 0 && i < n && margins[i] < margins[i - 1] - noise &&
          margins[i] < margins[i + 1] - noise) {
        const Extremum lowest = refine_maximum([&](double x) { return -margin(s, x); }, thetas[i - 1], thetas[i + 1]);
        if (-lowest.value <= 0) bad = lowest.theta;
      }
      if (!std::isnan(bad)) {
        // Widen to the nearest samples that pass on either side, then bisect to the sign changes.
        int lo = i, hi = i;
        while (lo > 0 && margins[lo] <= 0) --lo;
        while (hi < n && margins[hi] <= 0) ++hi;
        const auto m = [&](double x) { return margin(s, x); };
        const double from = margins[lo] > 0 ? bisect_sign_change(m, thetas[lo], bad) : thetas[lo];
        const double to = margins[hi] > 0 ? bisect_sign_change(m, bad, thetas[hi]) : thetas[hi];
        not_single_valued(from, to, t->trace);
      }
    }
    for (int i = s == 0 ? 0 : 1; i <= n; ++i) {
      t->psi.push_back(t->psi.empty() ? raw_psi[i] : t->psi.back() + std::remainder(raw_psi[i] - t->psi.back(), kTwoPi));
      t->theta.push_back(thetas[i]);
      if (i > 0) {
        t->segment.push_back(s);
        t->rate_lo.push_back(t->direction * margins[i - 1]);
        t->rate_hi.push_back(t->direction * margins[i]);
      }
    }
  }
  const double winding = (t->psi.back() - t->psi.front()) / kTwoPi;
  if (std::abs(winding - t->direction) > 1e-6)
    throw InputError("cam " + t->trace.what + " winds " + number_text(winding) +
                     " times around the cam centre over 0° to 360° instead of once; it is not "
                     "single-valued in polar angle");
  return t;
}

// The cubic Hermite interpolant of θ(ψ) on table interval i (dθ/dψ = 1/ψ') at ψ = target: within
// ~h⁴ of the root of ψ(θ) = target.
double hermite_start(const CurveTable& t, int i, double target) {
  const double lo = t.theta[i], hi = t.theta[i + 1];
  const double p0 = t.psi[i], p1 = t.psi[i + 1];
  if (p1 == p0) return lo;
  const double h = p1 - p0, x = (target - p0) / h, x2 = x * x, x3 = x2 * x;
  const double theta = (2 * x3 - 3 * x2 + 1) * lo + (x3 - 2 * x2 + x) * h / t.rate_lo[i] +
                       (-2 * x3 + 3 * x2) * hi + (x3 - x2) * h / t.rate_hi[i];
  return theta >= lo && theta <= hi ? theta : lo + (hi - lo) * x;
}

// ψ(θ) − target for the curve point xy at θ in table interval i (ψ unwrapped next to the
// interval's start).
double psi_residual(const CurveTable& t, int i, const Jet* xy, double target) {
  const double p0 = t.psi[i];
  return p0 + std::remainder(std::atan2(xy[1][0], xy[0][0]) - p0, kTwoPi) - target;
}

// θ with ψ(θ) = target inside table interval i, by Newton's method safeguarded by bisection,
// started from the Hermite interpolant, so one step usually settles it.
double invert(const CurveTable& t, int i, double target) {
  double lo = t.theta[i], hi = t.theta[i + 1];
  double theta = hermite_start(t, i, target);
  // A Newton step this small leaves an error of order step² · ψ''/ψ': below round-off.
  constexpr double kSettled = 1e-9;
  for (int iter = 0; iter < 100; ++iter) {
    Jet xy[2];
    curve_jets(t, t.segment[i], theta, 1, xy);
    const double g = psi_residual(t, i, xy, target);
    if (g == 0.0) return theta;
    (t.direction * g > 0 ? hi : lo) = theta;
    double next = theta - g / psi_rate(xy);
    const bool newton = next >= lo && next <= hi;
    if (!newton) next = 0.5 * (lo + hi);
    const double step = std::abs(next - theta);
    if ((newton && step <= kSettled) ||
        step <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(theta)))
      return next;
    theta = next;
  }
  throw NumericalError("cam polar function: Newton inversion of ψ(θ) did not converge at ψ = " + number_text(target));
}

// R's derivatives up to order d (<= 3) at the curve point whose jets of order d in θ are xy: r(θ)
// and ψ(θ), then the inverse-function rule for R(ψ) = r(θ(ψ)) (Faà di Bruno).
void polar_derivatives(const Jet* xy, int d, double* out) {
  const Jet r = sqrt(xy[0] * xy[0] + xy[1] * xy[1]);
  out[0] = r[0];
  if (d == 0) return;
  const double p1 = psi_rate(xy), t1 = 1.0 / p1;
  out[1] = r[1] * t1;
  if (d == 1) return;
  // ψ' as a jet: its derivatives enter from R″ on.
  const Jet rate =
      (xy[0] * xy[1].derivative() - xy[1] * xy[0].derivative()) / (xy[0] * xy[0] + xy[1] * xy[1]);
  const double p2 = rate[1], t2 = -p2 * t1 * t1 * t1;
  out[2] = r[2] * t1 * t1 + r[1] * t2;
  if (d == 2) return;
  const double t3 = (3 * p2 * p2 - p1 * rate[2]) * t1 * t1 * t1 * t1 * t1;
  out[3] = r[3] * t1 * t1 * t1 + 3 * r[2] * t1 * t2 + r[1] * t3;
}

}  // namespace

PolarFunction cam_polar_function(const PlateCam& cam, CamCurve curve) {
  const bool radial_knife = cam.follower().kind == FollowerKind::KnifeEdge && cam.follower().offset == 0.0;
  if (radial_knife) return displacement_polar_function(cam.program(), cam.rotation(), cam.base_radius());
  CamTrace trace{cam.program(),
                 cam.rotation(),
                 {},
                 curve == CamCurve::Contour ? "contour" : "pitch curve",
                 remedy(cam, curve)};
  if (curve == CamCurve::Contour)
    trace.point = [cam](int seg, double theta, int d, Eigen::Vector2d* out) {
      cam.contour_in_segment(seg, theta, d, out);
    };
  else
    trace.point = [cam](int seg, double theta, int d, Eigen::Vector2d* out) {
      cam.pitch_in_segment(seg, theta, d, out);
    };
  return traced_polar_function(std::move(trace));
}

PolarFunction roller_image_polar_function(const PlateCam& cam, const RollerImage& image,
                                          std::string what, std::string remedy) {
  CamTrace trace{cam.program(), cam.rotation(), {}, std::move(what), std::move(remedy)};
  trace.point = [cam, image](int seg, double theta, int d, Eigen::Vector2d* out) {
    Eigen::Vector2d centre[4];
    cam.roller_image_in_segment(seg, theta, d, image, centre, out);
  };
  return traced_polar_function(std::move(trace));
}

PolarFunction traced_polar_function(CamTrace trace) {
  std::shared_ptr<const CurveTable> table = build_table(std::move(trace));
  PolarFunction f;
  const double psi0 = table->psi.front();  // θ = 0
  f.start = table->direction > 0 ? psi0 : psi0 - kTwoPi;
  f.end = f.start + kTwoPi;
  for (double theta : table->trace.program.smoothness_breaks()) {
    // ψ of the curve point at θ, unwrapped next to the table's value at the interval's start.
    const int i = static_cast<int>(std::upper_bound(table->theta.begin(), table->theta.end(), theta) -
                                   table->theta.begin()) - 1;
    Jet xy[2];
    curve_jets(*table, table->segment[std::min(i, static_cast<int>(table->segment.size()) - 1)],
               theta, 0, xy);
    f.breakpoints.push_back(table->psi[i] +
                            std::remainder(std::atan2(xy[1][0], xy[0][0]) - table->psi[i], kTwoPi));
  }
  std::sort(f.breakpoints.begin(), f.breakpoints.end());

  f.derivatives = [table, start = f.start](double psi, int d, double* out) {
    const CurveTable& t = *table;
    // The domain [start, start + 2π] is the table's range; reduce periodically into it.
    psi -= kTwoPi * std::floor((psi - start) / kTwoPi);
    const auto before = [&](double a, double b) { return t.direction > 0 ? a < b : a > b; };
    const auto it = std::upper_bound(t.psi.begin(), t.psi.end(), psi, before);
    const int i = std::clamp(static_cast<int>(it - t.psi.begin()) - 1, 0, static_cast<int>(t.psi.size()) - 2);
    if (d < kMaxOrder) {
      // The curve point at the Hermite start θ₀, whose polar angle ψ₀ misses ψ by g: R's
      // derivatives up to order d + 1 at ψ₀, each taken back to ψ along its Taylor series,
      // R⁽ᵏ⁾(ψ) = R⁽ᵏ⁾(ψ₀) − g·R⁽ᵏ⁺¹⁾(ψ₀). The term left, R⁽ᵏ⁺²⁾·g²/2, is at most
      // 5e-19·|R⁽ᵏ⁺²⁾| when |g| <= 1e-9 rad (1e-13 mm in R for |R''| < 2·10⁵ mm), as g is in 2533
      // of the 2558 calls of the roller example's conversion at 1 µm (518 of its table's 519):
      // one curve evaluation instead of Newton's two or three and the last one.
      constexpr double kFirstOrder = 1e-9;
      const double theta0 = hermite_start(t, i, psi);
      Jet xy[2];
      curve_jets(t, t.segment[i], theta0, d + 1, xy);
      const double g = psi_residual(t, i, xy, psi);
      if (std::abs(g) <= kFirstOrder) {
        double at0[kMaxOrder + 1];
        polar_derivatives(xy, d + 1, at0);
        for (int k = 0; k <= d; ++k) out[k] = at0[k] - g * at0[k + 1];
        return;
      }
    }
    Jet xy[2];
    curve_jets(t, t.segment[i], invert(t, i, psi), d, xy);
    polar_derivatives(xy, d, out);
  };
  return f;
}

}  // namespace polarform
