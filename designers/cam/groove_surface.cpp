#include "designers/cam/groove_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "designers/cam/groove_height_fit.h"
#include "designers/cam/groove_wall.h"
#include "designers/convert/refined_maximum.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/common_basis.h"
#include "src/nurbs/knots.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

namespace {

constexpr int kSurfacePerSpanU = 12, kSurfacePerSpanV = 8, kRetries = 3;

// Arc breaks: the segment boundaries of the track (where the wall's smoothness drops), each piece
// split into equal arcs of at most max_sweep.
std::vector<double> arc_breaks(const BarrelCam& cam, double max_sweep) {
  const PolarFunction H = cam.track_height();
  std::vector<double> forced{H.start};
  forced.insert(forced.end(), H.breakpoints.begin(), H.breakpoints.end());
  forced.push_back(H.end);
  std::vector<double> out{H.start};
  for (std::size_t i = 0; i + 1 < forced.size(); ++i) {
    const int n = static_cast<int>(std::ceil((forced[i + 1] - forced[i]) / max_sweep - 1e-9));
    for (int k = 1; k <= n; ++k) out.push_back(forced[i] + (forced[i + 1] - forced[i]) * k / n);
  }
  return out;
}

// (ρ·X^w, ρ·Y^w, Z·W, W): the factors (ρ, Z, 1) on one basis times the circle's rows (Bae 2002,
// eq. (B.3) with ρ(v) in place of F).
NurbsSurface wall_surface(const BaseCircle& base, const BSplineSurface& Z) {
  const double u0 = Z.front_u(), u1 = Z.back_u(), r0 = Z.front_v(), r1 = Z.back_v();
  const BSplineSurface rho(0, 1, {u0, u1}, {r0, r0, r1, r1}, Eigen::MatrixXd{{r0, r1}});
  const BSplineSurface one(0, 0, {u0, u1}, {r0, r1}, Eigen::MatrixXd::Ones(1, 1));
  const BSpline& c = base.curve().homogeneous();
  const BSplineSurface circle(c.degree(), 0, c.knots(), {r0, r1}, c.coefs());
  return NurbsSurface(
      product_rows(common_basis({rho, Z, one}), {0, 0, 1, 2}, circle, {0, 1, 2, 2}));
}

// Max |z − h(ψ, ρ)| over samples of S, ψ and ρ taken from each sampled point itself: a grid
// per knot span, then golden-section refinement (Kiefer 1953) around the largest sample, along u
// and then along ρ, twice.
double surface_error(const NurbsSurface& S, const BaseCircle& base, const GrooveWall& wall,
                     const BSplineSurface& Z, int* samples) {
  std::vector<double> ub, vb;
  for (const Breakpoint& b : breakpoints(Z.knots_u())) ub.push_back(b.value);
  ub.insert(ub.end(), base.parameters().begin(), base.parameters().end());
  std::sort(ub.begin(), ub.end());
  ub.erase(std::unique(ub.begin(), ub.end()), ub.end());
  for (const Breakpoint& b : breakpoints(Z.knots_v())) vb.push_back(b.value);
  if (vb.size() < 2) vb = {S.front_v(), S.back_v()};
  const auto gap = [&](double u, double v) {
    const Eigen::Vector3d p = S.point(u, v);
    double psi = std::atan2(p.y(), p.x());
    psi += 2 * std::numbers::pi * std::round((base.angle(u) - psi) / (2 * std::numbers::pi));
    return std::abs(p.z() - wall.height(psi, std::hypot(p.x(), p.y())));
  };
  double worst = 0.0, wu = ub.front(), wv = vb.front(), du = 0.0;
  *samples = 0;
  for (std::size_t i = 0; i + 1 < ub.size(); ++i)
    for (int a = 0; a < kSurfacePerSpanU; ++a) {
      const double u = ub[i] + (ub[i + 1] - ub[i]) * (a + 0.5) / kSurfacePerSpanU;
      for (std::size_t j = 0; j + 1 < vb.size(); ++j)
        for (int b = 0; b <= kSurfacePerSpanV; ++b) {
          const double v = vb[j] + (vb[j + 1] - vb[j]) * b / kSurfacePerSpanV;
          const double e = gap(u, v);
          if (e > worst) worst = e, wu = u, wv = v, du = (ub[i + 1] - ub[i]) / kSurfacePerSpanU;
          ++*samples;
        }
    }
  const double dv = (vb.back() - vb.front()) / (kSurfacePerSpanV * (vb.size() - 1.0));
  for (int round = 0; round < 2; ++round) {
    const Maximum mu =
        refined_maximum([&](double u) { return gap(u, wv); },
                        {std::max(S.front_u(), wu - du), std::min(S.back_u(), wu + du)}, 8, 1);
    wu = mu.at;
    const Maximum mv =
        refined_maximum([&](double v) { return gap(wu, v); },
                        {std::max(S.front_v(), wv - dv), std::min(S.back_v(), wv + dv)}, 8, 1);
    wv = mv.at;
    worst = std::max({worst, mu.value, mv.value});
  }
  return worst;
}

// One wall on arcs of at most max_sweep: Z fitted to a share of the tolerance, halved until the
// error measured on the surface meets the tolerance.
GrooveSurface wall_with_arcs(const BarrelCam& cam, const GrooveWall& wall,
                             const GrooveOptions& options, double max_sweep) {
  GrooveSurface out;
  out.side = wall.side();
  out.tolerance = options.tolerance;
  out.base = BaseCircle(ArcKind::quartic, arc_breaks(cam, max_sweep), options.alpha);
  const auto h = [&wall](double psi, double rho) { return wall.height(psi, rho); };
  double target = options.fit_share * options.tolerance;
  for (int attempt = 0;; ++attempt, target *= 0.5) {
    const HeightFit fit =
        fit_groove_height(h, out.base, options.inner_radius, options.outer_radius, target);
    out.height = fit.Z;
    out.fit_error = fit.max_error;
    out.surface = wall_surface(out.base, fit.Z);
    out.max_error = surface_error(out.surface, out.base, wall, fit.Z, &out.samples);
    if (out.max_error <= options.tolerance) return out;
    if (attempt == kRetries)
      throw NumericalError("groove surface: measured error " + number_text(out.max_error) +
                           " mm exceeds the tolerance " + number_text(options.tolerance) + " mm");
  }
}

}  // namespace

GrooveSurface groove_surface(const BarrelCam& cam, int side, const GrooveOptions& options) {
  const GrooveWall wall(cam, side);
  if (!(options.inner_radius >= wall.min_radius()) ||
      !(options.outer_radius > options.inner_radius) || !std::isfinite(options.outer_radius))
    throw InputError("groove surface: radii " + number_text(options.inner_radius) + " … " +
                     number_text(options.outer_radius) + " mm: expected √2·Rr = " +
                     number_text(wall.min_radius()) + " mm <= inner < outer");
  if (!(options.tolerance > 0)) throw InputError("groove surface: tolerance must be > 0 mm");
  if (!(options.fit_share > 0 && options.fit_share <= 1))
    throw InputError("groove surface: fit_share must lie in (0, 1]");

  // Longer arcs mean fewer C0 knots but a less uniform angle(u) for Z to follow: build both and
  // keep the smaller control net that meets the tolerance.
  std::optional<GrooveSurface> best;
  for (double sweep : {std::numbers::pi, std::numbers::pi / 2}) {
    GrooveSurface g = wall_with_arcs(cam, wall, options, sweep);
    if (!best ||
        g.surface.size_u() * g.surface.size_v() < best->surface.size_u() * best->surface.size_v())
      best = std::move(g);
  }
  return *best;
}

}  // namespace polarform
