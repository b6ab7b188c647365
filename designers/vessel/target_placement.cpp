#include "designers/vessel/target_placement.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/vessel/membrane_stress.h"
#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSamples = 720;  // equal steps of θ over [0, π] bracketing every place

double meridian_angle(const PolarFunction& R, double theta) {
  double d[2];
  R.derivatives(theta, 1, d);
  return kPi - theta - std::atan2(d[0], d[1]);
}

// The first θ in [0, π] where g(θ) = goal, g sampled at kSamples + 1 angles then bisected.
template <class G>
bool first_crossing(G&& g, double goal, double& theta) {
  double a = 0.0, ga = g(a) - goal;
  if (ga == 0.0) return theta = a, true;
  for (int i = 1; i <= kSamples; ++i) {
    const double b = kPi * i / kSamples, gb = g(b) - goal;
    if (gb == 0.0) return theta = b, true;
    if ((ga < 0) != (gb < 0)) {
      double lo = a, hi = b, glo = ga;
      for (int k = 0; k < 60 && hi - lo > 1e-15; ++k) {
        const double mid = 0.5 * (lo + hi), gm = g(mid) - goal;
        if ((gm < 0) == (glo < 0))
          lo = mid, glo = gm;
        else
          hi = mid;
      }
      return theta = 0.5 * (lo + hi), true;
    }
    a = b, ga = gb;
  }
  return false;
}

}  // namespace

const char* target_place_symbol(TargetPlace place) {
  switch (place) {
    case TargetPlace::arc_length:
      return "s";
    case TargetPlace::meridian_angle:
      return "φ";
    case TargetPlace::polar_angle:
      break;
  }
  return "θ";
}

double place_targets(std::vector<CurvatureTarget>& targets, const PolarFunction& R) {
  // s(θ) on the sample grid, then within a step by 8-interval Gauss–Legendre from the step's start.
  std::vector<double> s(kSamples + 1, 0.0);
  for (int i = 1; i <= kSamples; ++i)
    s[i] = s[i - 1] + arc_length(R, kPi * (i - 1) / kSamples, kPi * i / kSamples, 2);
  const auto arc = [&](double theta) {
    const int i = std::clamp(static_cast<int>(theta / kPi * kSamples), 0, kSamples - 1);
    return s[i] + arc_length(R, kPi * i / kSamples, theta, 8);
  };
  double moved = 0.0;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    CurvatureTarget& t = targets[k];
    if (t.place == TargetPlace::polar_angle) continue;
    double theta = 0.0;
    const bool found =
        t.place == TargetPlace::arc_length
            ? first_crossing(arc, t.position, theta)
            : first_crossing([&](double a) { return -meridian_angle(R, a); }, -t.position, theta);
    if (!found) {
      const bool by_s = t.place == TargetPlace::arc_length;
      throw InputError("vessel: curvature target " + std::to_string(k + 1) + " at " +
                       (by_s ? "s = " + to_text(t.position) + " mm"
                             : "φ = " + to_text(t.position * 180 / kPi) + "°") +
                       " is not on the head's meridian (" +
                       (by_s
                            ? "its length is " + to_text(s.back()) + " mm"
                            : "φ runs from 90° at junction A to " +
                                  to_text(meridian_angle(R, kPi) * 180 / kPi) + "° at junction B") +
                       ")");
    }
    moved = std::max(moved, std::abs(theta - t.theta));
    t.theta = theta;
  }
  return moved;
}

void place_targets_on_circle(std::vector<CurvatureTarget>& targets, double radius) {
  for (CurvatureTarget& t : targets) {
    if (t.place == TargetPlace::arc_length) t.theta = std::clamp(t.position / radius, 0.0, kPi);
    if (t.place == TargetPlace::meridian_angle)
      t.theta = std::clamp(kPi / 2 - t.position, 0.0, kPi);
  }
}

}  // namespace polarform
