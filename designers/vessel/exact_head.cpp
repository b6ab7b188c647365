#include "designers/vessel/exact_head.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "src/error.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

// One rational quadratic segment: end points, middle control point and its weight (end weights 1).
struct ConicArc {
  Eigen::Vector2d start, middle, end;
  double weight;
};

Eigen::Vector2d direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

// The circular arc about `centre` of radius r from angle a0 to a1 (|a1 − a0| <= π/2): the middle
// point where the end tangents meet, weight cos of half the sweep (NURBS Book eq. (7.33)).
ConicArc circular_arc(const Eigen::Vector2d& centre, double r, double a0, double a1) {
  const double half = 0.5 * (a1 - a0), mid = 0.5 * (a0 + a1);
  return {centre + r * direction(a0), centre + r / std::cos(half) * direction(mid),
          centre + r * direction(a1), std::cos(half)};
}

// The straight segment from a to b as a rational quadratic: middle point the midpoint, weight 1.
ConicArc straight(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return {a, 0.5 * (a + b), b, 1.0};
}

// A quarter of the ellipse x²/a² + z²/b² = 1 from (sign·a, 0) to the apex (0, b) or back: the
// affine image of a circular quarter, middle point the corner (sign·a, b), weight √2/2.
ConicArc elliptic_quarter(double a, double b, bool to_apex) {
  const double w = std::sqrt(0.5);
  return to_apex ? ConicArc{{a, 0.0}, {a, b}, {0.0, b}, w}
                 : ConicArc{{0.0, b}, {-a, b}, {-a, 0.0}, w};
}

// The segments as one curve, segment i on [i, i + 1], double knots at the joints.
NurbsCurve2d joined(const std::vector<ConicArc>& arcs) {
  Knots knots = {0.0, 0.0, 0.0};
  NurbsCurve2d::Points points = {arcs.front().start};
  std::vector<double> weights = {1.0};
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    const double end = static_cast<double>(i + 1);
    knots.insert(knots.end(), {end, end});
    points.insert(points.end(), {arcs[i].middle, arcs[i].end});
    weights.insert(weights.end(), {arcs[i].weight, 1.0});
  }
  knots.push_back(static_cast<double>(arcs.size()));
  return NurbsCurve2d(2, std::move(knots), points, weights);
}

}  // namespace

ExactHead exact_head(const HeadPreset& preset, double radius) {
  ExactHead out;
  out.shape = head_shape(preset, radius);  // validates the parameters
  std::vector<ConicArc> arcs;
  const Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  switch (preset.kind) {
    case HeadKind::hemispherical:
      arcs = {circular_arc(origin, radius, 0.0, kPi / 2),
              circular_arc(origin, radius, kPi / 2, kPi)};
      break;
    case HeadKind::ellipsoidal: {
      const double depth = radius / preset.ratio;
      arcs = {elliptic_quarter(radius, depth, true), elliptic_quarter(radius, depth, false)};
      break;
    }
    case HeadKind::torispherical: {
      // Knuckle centre (R − rk, 0), crown centre (0, zc) on the axis, |centres| = rc − rk; the
      // joint lies on the line of centres, at angle α seen from either centre.
      const double rk = preset.knuckle, rc = preset.crown, kx = radius - rk;
      const double zc = -std::sqrt((rc - rk) * (rc - rk) - kx * kx);
      const double alpha = std::atan2(-zc, kx);
      arcs = {circular_arc({kx, 0.0}, rk, 0.0, alpha), circular_arc({0.0, zc}, rc, alpha, kPi / 2),
              circular_arc({0.0, zc}, rc, kPi / 2, kPi - alpha),
              circular_arc({-kx, 0.0}, rk, kPi - alpha, kPi)};
      break;
    }
    case HeadKind::conical:
    case HeadKind::flat: {
      // The knuckle about (R − r, 0) turns by α to T, the cone runs straight to the apex (a flat
      // head's: α = 90°, the plate z = r).
      const double rk = preset.knuckle;
      const auto [alpha, g] = knuckled_head_geometry(preset, radius);
      const Eigen::Vector2d t{g.tangent_x, g.tangent_z}, apex{0.0, g.apex_z};
      const Eigen::Vector2d mirror{-1.0, 1.0};
      if (rk > 0.0) arcs.push_back(circular_arc({g.knuckle_centre_x, 0.0}, rk, 0.0, alpha));
      arcs.push_back(straight(t, apex));
      arcs.push_back(straight(apex, t.cwiseProduct(mirror)));
      if (rk > 0.0) arcs.push_back(circular_arc({-g.knuckle_centre_x, 0.0}, rk, kPi - alpha, kPi));
      break;
    }
  }
  out.meridian = joined(arcs);
  out.arcs = static_cast<int>(arcs.size());
  return out;
}

double exact_head_deviation(const NurbsCurve2d& meridian, const HeadShape& shape, int samples) {
  if (samples < 2)
    throw InputError("exact head deviation: " + std::to_string(samples) +
                     " samples per segment, expected >= 2");
  double worst = 0.0;
  const std::vector<Breakpoint> breaks = breakpoints(meridian.knots());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    for (int k = 0; k < samples; ++k) {
      const double a = breaks[i].value, b = breaks[i + 1].value;
      const Eigen::Vector2d p = meridian.point(a + (b - a) * k / (samples - 1.0));
      const double theta = std::atan2(p.y(), p.x());
      worst = std::max(worst, std::abs(p.norm() - shape.profile(std::clamp(theta, 0.0, kPi))));
    }
  return worst;
}

}  // namespace polarform
