#include "src/fit/revolution_test.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/fit/f_distribution.h"
#include "src/fit/net_selection.h"

namespace polarform {

const char* revolution_word(RevolutionMode m) {
  switch (m) {
    case RevolutionMode::automatic:
      return "auto";
    case RevolutionMode::yes:
      return "yes";
    case RevolutionMode::no:
      return "no";
  }
  return "?";
}

FunctionSpace rotational_space(const FunctionSpace& space) {
  FunctionSpace s = space;
  s.periodic_v = s.symmetric_v = false;
  return s;
}

FunctionFitOptions rotational_options(const FunctionFitOptions& options) {
  FunctionFitOptions o = options;
  o.degree_v = 0;
  o.size_v = o.max_size_v = 1;
  return o;
}

// Draper & Smith, Applied Regression Analysis, §6.2: the extra-sum-of-squares F-test.
RevolutionTest test_revolution(const Samples& all, const FunctionSpace& space,
                               const FunctionFitOptions& options, int size_u, int size_v) {
  const Samples s = strided_subsample(all, kSelectionSamples);
  const NetCandidate rot =
      evaluate_net(s, rotational_space(space), rotational_options(options), size_u, 1);
  const NetCandidate full = evaluate_net(s, space, options, size_u, size_v);
  RevolutionTest t;
  t.mode = RevolutionMode::automatic;
  t.tested = true;
  t.samples = s.size();
  t.size_u = size_u, t.size_v = size_v;
  t.params_rotational = rot.coefficients, t.params_full = full.coefficients;
  t.rms_rotational = rot.rms, t.rms_full = full.rms;
  t.gcv_rotational = rot.gcv, t.gcv_full = full.gcv;
  const double n = static_cast<double>(s.size());
  const double d1 = std::max(1.0, double(full.coefficients - rot.coefficients));
  const double d2 = std::max(1.0, n - double(full.coefficients));
  const double rss0 = rot.rms * rot.rms * n, rss1 = full.rms * full.rms * n;
  t.threshold = f_critical_value(kRevolutionAlpha, d1, d2);
  const double scale = std::max(s.value.cwiseAbs().maxCoeff(), 1e-300);
  std::ostringstream why;
  why.precision(4);
  if (rot.rms <= 1e-12 * scale) {
    t.f_statistic = 0.0, t.p_value = 1.0, t.rotational = true;
    why << "F(u) alone fits the samples exactly (rms " << rot.rms << " mm)";
  } else {
    t.f_statistic = rss1 > 0.0 ? std::max(0.0, (rss0 - rss1) / d1) / (rss1 / d2) : HUGE_VAL;
    t.p_value = f_upper_tail(t.f_statistic, d1, d2);
    t.rotational = t.p_value >= kRevolutionAlpha;
    why << "F-test of F(u) (" << rot.coefficients << " coefficients, rms " << rot.rms
        << " mm) against F(u, v) (" << full.coefficients << ", rms " << full.rms << " mm) on "
        << s.size() << " samples: F = " << t.f_statistic << (t.rotational ? " <= " : " > ")
        << t.threshold << " (p = " << t.p_value << ", level " << kRevolutionAlpha << "): "
        << (t.rotational ? "no variation around the axis beyond the noise"
                         : "F varies around the axis beyond the noise");
  }
  t.reason = why.str();
  return t;
}

}  // namespace polarform
