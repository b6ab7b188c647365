// Whether F varies around the axis beyond the noise: the F-test of the nested least-squares models
// F(u) alone (constant in v ↔ θ) against F(u, v) on the same u knots (Draper & Smith, §6.2). When
// the variation is not significant the fit is made exactly rotational — a surface of revolution
// of degree (p, 2) for cylindrical fits, (p + 2, 2) for spherical ones, a circle for profiles
// (Bae 2002, §6; DESIGN §4.1) — instead of carrying the noise in spurious θ-terms.
#pragma once

#include <string>

#include "src/fit/function_fit.h"

namespace polarform {

enum class RevolutionMode { automatic, yes, no };
const char* revolution_word(RevolutionMode mode);  // "auto", "yes", "no"

// The significance level of the test: rotational unless P(F > f) < kRevolutionAlpha.
constexpr double kRevolutionAlpha = 1e-3;

struct RevolutionTest {
  RevolutionMode mode = RevolutionMode::no;
  bool tested = false;      // the F-test ran (automatic mode)
  bool rotational = false;  // F was fitted constant in v
  std::size_t samples = 0;
  int size_u = 0, size_v = 0;  // the F(u, v) net F(u) (size_u) was tested against
  long params_rotational = 0, params_full = 0;
  double rms_rotational = 0.0, rms_full = 0.0;  // parametric residuals, mm
  double gcv_rotational = 0.0, gcv_full = 0.0;
  double f_statistic = 0.0, threshold = 0.0, p_value = 1.0;
  std::string reason;
};

// The space and options of F(u) alone: degree 0 and one coefficient along v, not periodic.
FunctionSpace rotational_space(const FunctionSpace& space);
FunctionFitOptions rotational_options(const FunctionFitOptions& options);

// f = ((RSS₀ − RSS₁)/(m₁ − m₀)) / (RSS₁/(n − m₁)) of F(u) (size_u) against F(u, v) (size_u x
// size_v) on the samples; rotational when P(F > f) >= kRevolutionAlpha.
RevolutionTest test_revolution(const Samples& samples, const FunctionSpace& space,
                               const FunctionFitOptions& options, int size_u, int size_v);

}  // namespace polarform
