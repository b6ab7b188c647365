#include "designers/vessel/head_preset.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "designers/vessel/meridian_arcs.h"
#include "designers/vessel/polar_curvature.h"
#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

std::string short_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

PolarFunction piece(double start, double end, std::function<void(double, int, double*)> R) {
  PolarFunction f;
  f.start = start;
  f.end = end;
  f.derivatives = std::move(R);
  return f;
}

double curvature_at(const PolarFunction& f, double theta) {
  double d[3];
  f.derivatives(theta, 2, d);
  return polar_curvature(d[0], d[1], d[2]);
}

// The pieces as one function; θ on a joint takes the lower piece.
PolarFunction joined(const std::vector<PolarFunction>& pieces) {
  PolarFunction f;
  f.start = 0.0;
  f.end = kPi;
  for (std::size_t i = 1; i < pieces.size(); ++i) f.breakpoints.push_back(pieces[i].start);
  f.breakpoints.push_back(kPi / 2);
  std::sort(f.breakpoints.begin(), f.breakpoints.end());
  f.breakpoints.erase(std::unique(f.breakpoints.begin(), f.breakpoints.end()), f.breakpoints.end());
  f.derivatives = [pieces](double theta, int d, double* out) {
    std::size_t i = 0;
    while (i + 1 < pieces.size() && theta > pieces[i].end) ++i;
    pieces[i].derivatives(theta, d, out);
  };
  return f;
}

}  // namespace

const char* head_kind_name(HeadKind kind) {
  switch (kind) {
    case HeadKind::hemispherical: return "hemispherical";
    case HeadKind::ellipsoidal: return "ellipsoidal";
    case HeadKind::torispherical: return "torispherical";
    case HeadKind::conical:
      return "conical";
    case HeadKind::flat:
      return "flat";
  }
  return "";
}

HeadPreset torispherical_100_6(double radius) {
  return {HeadKind::torispherical, 2.0, 2 * radius, 0.12 * radius};
}

HeadPreset torispherical_80_10(double radius) {
  return {HeadKind::torispherical, 2.0, 1.6 * radius, 0.2 * radius};
}

// |apex − crown centre| = L and |knuckle centre − crown centre| = L − r, solved for L.
HeadPreset torispherical_of_depth(double radius, double depth, double knuckle) {
  if (!(knuckle > 0.0 && knuckle < depth))
    throw InputError("torispherical head of depth " + to_text(depth) + " mm: knuckle " +
                     to_text(knuckle) + " mm, expected 0 < knuckle < depth");
  const double a = radius, h = depth, r = knuckle;
  // L − a = (a − h)² / (2 (h − r)) >= 0: the crown is never smaller than the radius.
  return {HeadKind::torispherical, 2.0, (h * h - r * r + (a - r) * (a - r)) / (2 * (h - r)),
          knuckle};
}

namespace {

// The knuckle about (R − r, 0) turned by α, then a straight line to the axis (α = 90°: exactly
// the plate z = r, which cos/sin of π/2 would leave 1e-17 off).
ConeGeometry knuckled_line(double radius, double half_angle, double knuckle) {
  ConeGeometry g;
  g.knuckle_centre_x = radius - knuckle;
  const bool flat = half_angle == kPi / 2;
  g.tangent_x = g.knuckle_centre_x + (flat ? 0.0 : knuckle * std::cos(half_angle));
  g.tangent_z = flat ? knuckle : knuckle * std::sin(half_angle);
  g.apex_z = flat ? knuckle : g.tangent_z + g.tangent_x / std::tan(half_angle);
  return g;
}

}  // namespace

ConeGeometry cone_geometry(double radius, double half_angle, double knuckle) {
  if (!(half_angle > 0.0 && half_angle < kPi / 2))
    throw InputError("head preset: conical half angle " + short_text(half_angle * 180 / kPi) +
                     "°, expected 0° < α < 90°");
  if (!(knuckle >= 0.0 && knuckle < radius))
    throw InputError("head preset: conical knuckle " + to_text(knuckle) +
                     " mm, expected 0 <= knuckle < radius = " + to_text(radius) + " mm");
  return knuckled_line(radius, half_angle, knuckle);
}

ConeGeometry flat_head_geometry(double radius, double knuckle) {
  if (!(knuckle > 0.0 && knuckle < radius))
    throw InputError("head preset: flat head knuckle " + to_text(knuckle) +
                     " mm, expected 0 < knuckle < radius = " + to_text(radius) +
                     " mm (a flat plate without a knuckle has no polar meridian)");
  return knuckled_line(radius, kPi / 2, knuckle);
}

std::pair<double, ConeGeometry> knuckled_head_geometry(const HeadPreset& preset, double radius) {
  if (preset.kind == HeadKind::flat) return {kPi / 2, flat_head_geometry(radius, preset.knuckle)};
  return {preset.half_angle, cone_geometry(radius, preset.half_angle, preset.knuckle)};
}

HeadShape head_shape(const HeadPreset& preset, double radius) {
  if (!(radius > 0.0 && std::isfinite(radius)))
    throw InputError("head preset: radius " + to_text(radius) + " mm, expected > 0");
  HeadShape shape;
  switch (preset.kind) {
    case HeadKind::hemispherical:
      shape.name = "hemispherical";
      shape.pieces.push_back(piece(0.0, kPi, [radius](double, int d, double* out) {
        out[0] = radius;
        for (int k = 1; k <= d; ++k) out[k] = 0.0;
      }));
      break;
    case HeadKind::ellipsoidal: {
      if (!(preset.ratio > 0.0 && std::isfinite(preset.ratio)))
        throw InputError("head preset: ellipsoidal ratio " + to_text(preset.ratio) +
                         ", expected radius/depth > 0");
      const double depth = radius / preset.ratio;
      shape.name = short_text(preset.ratio) + ":1 semi-ellipsoidal";
      shape.pieces.push_back(piece(0.0, kPi, [radius, depth](double t, int d, double* out) {
        ellipse_polar(radius, depth, t, d, out);
      }));
      break;
    }
    case HeadKind::torispherical: {
      const double R = radius, rc = preset.crown, rk = preset.knuckle;
      if (!(rk > 0.0 && rk < R))
        throw InputError("head preset: torispherical knuckle " + to_text(rk) +
                         " mm, expected 0 < knuckle < radius = " + to_text(R) + " mm");
      if (!(rc >= R && std::isfinite(rc)))
        throw InputError("head preset: torispherical crown " + to_text(rc) +
                         " mm, expected crown >= radius = " + to_text(R) + " mm");
      // Knuckle centre (R − rk, 0); crown centre (0, zc) on the axis, tangent to the knuckle
      // circle: |centres| = rc − rk. The joint lies on the line of centres, rc from the crown's.
      const double kx = R - rk, zc = -std::sqrt((rc - rk) * (rc - rk) - kx * kx);
      const double tx = rc * kx / (rc - rk), tz = zc + rc * (-zc) / (rc - rk);
      const double joint = std::atan2(tz, tx);
      shape.name = "torispherical, crown " + short_text(rc) + " mm, knuckle " + short_text(rk) + " mm";
      shape.pieces.push_back(piece(0.0, joint, [kx, rk](double t, int d, double* out) {
        circle_polar(kx, 0.0, rk, t, d, out);
      }));
      shape.pieces.push_back(piece(joint, kPi - joint, [zc, rc](double t, int d, double* out) {
        circle_polar(0.0, zc, rc, t, d, out);
      }));
      shape.pieces.push_back(piece(kPi - joint, kPi, [kx, rk](double t, int d, double* out) {
        circle_polar(-kx, 0.0, rk, t, d, out);
      }));
      break;
    }
    case HeadKind::conical:
    case HeadKind::flat: {
      const bool flat = preset.kind == HeadKind::flat;
      const double rk = preset.knuckle;
      const auto [alpha, g] = knuckled_head_geometry(preset, radius);
      // The cone's line has the outward normal (cos α, sin α) on side A, (−cos α, sin α) on B.
      const double joint = std::atan2(g.tangent_z, g.tangent_x);
      const double distance =
          flat ? rk : g.tangent_x * std::cos(alpha) + g.tangent_z * std::sin(alpha);
      shape.name = flat ? "flanged flat, knuckle " + short_text(rk) + " mm"
                        : "conical, half angle " + short_text(alpha * 180 / kPi) + "°" +
                              (rk > 0.0 ? ", knuckle " + short_text(rk) + " mm" : std::string());
      if (flat) shape.plate_radius = g.knuckle_centre_x;
      const double kx = g.knuckle_centre_x;
      if (rk > 0.0)
        shape.pieces.push_back(piece(0.0, joint, [kx, rk](double t, int d, double* out) {
          circle_polar(kx, 0.0, rk, t, d, out);
        }));
      shape.pieces.push_back(piece(joint, kPi / 2, [alpha, distance](double t, int d, double* out) {
        line_polar(alpha, distance, t, d, out);
      }));
      shape.pieces.push_back(
          piece(kPi / 2, kPi - joint, [alpha, distance](double t, int d, double* out) {
            line_polar(kPi - alpha, distance, t, d, out);
          }));
      if (rk > 0.0)
        shape.pieces.push_back(piece(kPi - joint, kPi, [kx, rk](double t, int d, double* out) {
          circle_polar(-kx, 0.0, rk, t, d, out);
        }));
      break;
    }
  }
  shape.profile = joined(shape.pieces);
  shape.depth = shape.profile(kPi / 2);
  shape.jumps.push_back({0.0, 0.0, curvature_at(shape.pieces.front(), 0.0)});
  for (std::size_t i = 1; i < shape.pieces.size(); ++i) {
    const double at = shape.pieces[i].start;
    shape.jumps.push_back({at, curvature_at(shape.pieces[i - 1], at),
                           curvature_at(shape.pieces[i], at)});
  }
  shape.jumps.push_back({kPi, curvature_at(shape.pieces.back(), kPi), 0.0});
  return shape;
}

std::vector<CurvatureTarget> preset_targets(const HeadShape& shape, int count) {
  if (count < 1 || count > kMaxCurvatureTargets)
    throw InputError("head preset: " + std::to_string(count) +
                     " curvature targets, expected in [1, " + std::to_string(kMaxCurvatureTargets) +
                     "]");
  std::vector<CurvatureTarget> targets;
  for (int k = 0; k < count; ++k) {
    const double theta = (k + 0.5) * kPi / count;
    targets.push_back({theta, curvature_at(shape.profile, theta), 1.0});
  }
  return targets;
}

}  // namespace polarform
