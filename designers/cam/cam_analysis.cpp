#include "designers/cam/cam_analysis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/nurbs/curve_interpolation.h"
#include "src/nurbs/pipe_surface.h"

namespace polarform {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

void check_grid(std::span<const double> thetas) {
  if (thetas.size() < 2) throw InputError("cam analysis: need at least 2 angles, got " + std::to_string(thetas.size()));
  for (std::size_t i = 0; i < thetas.size(); ++i) {
    if (!std::isfinite(thetas[i]) || thetas[i] < 0 || thetas[i] > kTwoPi)
      throw InputError("cam analysis: angle " + std::to_string(i) + " outside [0, 2π] rad");
    if (i > 0 && !(thetas[i] > thetas[i - 1]))
      throw InputError("cam analysis: angles must increase, angle " + std::to_string(i) + " does not");
  }
}

// Maximum of value(segment, θ) over the grid, refined between the neighbours of the best sample,
// one segment at a time. `sampled` holds the value at each grid angle.
template <class Value>
Extremum refined_maximum(const CamProgram& program, std::span<const double> thetas, const std::vector<double>& sampled,
                         Value&& value) {
  const std::size_t best = std::max_element(sampled.begin(), sampled.end()) - sampled.begin();
  const double a = thetas[best == 0 ? 0 : best - 1], b = thetas[std::min(best + 1, thetas.size() - 1)];
  Extremum result{sampled[best], thetas[best]};
  const std::vector<MotionSegment>& segs = program.segments();
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    const double lo = std::max(a, segs[s].start()), hi = std::min(b, segs[s].end());
    if (!(lo < hi)) continue;
    const Extremum e = refine_maximum([&](double t) { return value(s, t); }, lo, hi);
    if (e.value > result.value) result = e;
  }
  return result;
}

template <class Field>
Extremum refined_sample_maximum(const PlateCam& cam, std::span<const double> thetas,
                                const std::vector<CamSample>& samples, Field&& field) {
  std::vector<double> sampled(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) sampled[i] = field(samples[i]);
  return refined_maximum(cam.program(), thetas, sampled,
                         [&](int s, double t) { return field(cam.sample_in_segment(s, t)); });
}

Extremum negated(Extremum e) { return {-e.value, e.theta}; }

// Smallest positive radius 1/κ from the largest κ of `sign` * curvature.
Extremum min_radius(Extremum max_curvature) {
  return max_curvature.value > 0 ? Extremum{1.0 / max_curvature.value, max_curvature.theta} : Extremum{kInf, 0.0};
}

}  // namespace

// MIT 13.472J (8.46) on the pitch curve: the roller as a planar pipe (M7).
PitchPipeBound pitch_pipe_bound(const PlateCam& cam, int samples) {
  std::vector<double> t = uniform_angles(samples);  // InputError below 2
  t.push_back(kTwoPi);
  for (const MotionSegment& s : cam.program().segments()) t.push_back(s.start());
  std::sort(t.begin(), t.end());
  // Nodes closer than 1e-9 rad are one (a boundary on the grid).
  t.erase(std::unique(t.begin(), t.end(), [](double a, double b) { return b - a < 1e-9; }),
          t.end());
  Eigen::MatrixXd points = Eigen::MatrixXd::Zero(3, static_cast<Eigen::Index>(t.size()));
  for (std::size_t k = 0; k < t.size(); ++k) {
    Eigen::Vector2d c;
    cam.pitch(std::min(t[k], kTwoPi), 0, &c);
    points.col(static_cast<Eigen::Index>(k)).head<2>() = c;
  }
  Eigen::Vector2d d[2];
  cam.pitch(0.0, 1, d);
  CubicEnds ends;
  ends.start_tangent = Eigen::VectorXd(Eigen::Vector3d(d[1].x(), d[1].y(), 0.0));
  ends.end_tangent = ends.start_tangent;
  const BSpline spline = interpolate_cubic(
      points, Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size())),
      ends);
  NurbsCurve3d::Points control;
  for (int i = 0; i < spline.size(); ++i) control.push_back(spline.coefs().col(i));
  const SpineCurvature k = max_curvature(NurbsCurve3d(spline.degree(), spline.knots(), control));
  return {k.kappa_max, 1.0 / k.kappa_max};
}

std::vector<double> uniform_angles(int count) {
  if (count < 2) throw InputError("cam analysis: need at least 2 angles, got " + std::to_string(count));
  std::vector<double> out(count);
  for (int k = 0; k < count; ++k) out[k] = kTwoPi * k / count;
  return out;
}

MotionExtrema motion_extrema(const CamProgram& program, std::span<const double> thetas) {
  check_grid(thetas);
  std::vector<std::array<double, 4>> samples(thetas.size());
  for (std::size_t i = 0; i < thetas.size(); ++i) program.derivatives(thetas[i], 3, samples[i].data());
  const auto extreme = [&](int k) {
    std::vector<double> sampled(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) sampled[i] = std::abs(samples[i][k]);
    return refined_maximum(program, thetas, sampled, [&](int seg, double t) {
      double s[4];
      program.segments()[seg].derivatives(t, 3, s);
      return std::abs(s[k]);
    });
  };
  return {extreme(1), extreme(2), extreme(3)};
}

CamAnalysis analyse(const PlateCam& cam, std::span<const double> thetas) {
  check_grid(thetas);
  CamAnalysis out;
  out.samples.reserve(thetas.size());
  for (double t : thetas) out.samples.push_back(cam.sample(t));
  const auto& samples = out.samples;
  const auto extreme = [&](auto field) { return refined_sample_maximum(cam, thetas, samples, field); };

  out.motion.velocity = extreme([](const CamSample& c) { return std::abs(c.v); });
  out.motion.acceleration = extreme([](const CamSample& c) { return std::abs(c.a); });
  out.motion.jerk = extreme([](const CamSample& c) { return std::abs(c.j); });
  out.max_pressure_angle = extreme([](const CamSample& c) { return std::abs(c.pressure_angle); });
  out.min_convex_pitch_radius = min_radius(extreme([](const CamSample& c) { return c.pitch_curvature; }));
  out.min_convex_contour_radius = min_radius(extreme([](const CamSample& c) { return c.contour_curvature; }));
  out.min_concave_contour_radius = min_radius(extreme([](const CamSample& c) { return -c.contour_curvature; }));
  out.min_contour_speed = negated(extreme([](const CamSample& c) { return -c.contour_speed; }));

  // Undercut: runs of failing samples, ends bisected against the neighbouring passing samples;
  // a dip found only by refinement is bracketed by the samples around it.
  const auto speed = [&](double t) { return cam.sample(t).contour_speed; };
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].contour_speed > 0) continue;
    std::size_t j = i;
    while (j + 1 < samples.size() && samples[j + 1].contour_speed <= 0) ++j;
    const double from = i > 0 ? bisect_sign_change(speed, thetas[i - 1], thetas[i]) : thetas[i];
    const double to = j + 1 < samples.size() ? bisect_sign_change(speed, thetas[j], thetas[j + 1]) : thetas[j];
    out.undercut.push_back({from, to});
    i = j;
  }
  const Extremum dip = out.min_contour_speed;
  if (dip.value <= 0 && out.undercut.empty()) {
    const auto after = std::upper_bound(thetas.begin(), thetas.end(), dip.theta);
    const double a = after == thetas.begin() ? thetas.front() : *(after - 1);
    const double b = after == thetas.end() ? thetas.back() : *after;
    out.undercut.push_back({speed(a) > 0 ? bisect_sign_change(speed, a, dip.theta) : a,
                            speed(b) > 0 ? bisect_sign_change(speed, dip.theta, b) : b});
  }

  if (is_flat_faced(cam.follower().kind)) {
    const auto contact = [](const CamSample& c) { return c.face_contact; };
    const Extremum right = extreme(contact);
    const Extremum left = negated(extreme([&](const CamSample& c) { return -contact(c); }));
    out.face_width = FaceWidth{left.value, right.value};
  }
  return out;
}

}  // namespace polarform
