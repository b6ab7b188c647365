// The model of F a geometric fit uses, chosen from the data before the fit proper: the control net
// by GCV over net sizes (net_selection.h) unless given, and whether F is constant around the axis
// by the F-test of F(u) against F(u, v) (revolution_test.h) unless asked. A tolerance below the
// noise the data shows is refused with the numbers.
#pragma once

#include "src/fit/function_fit.h"
#include "src/fit/net_selection.h"
#include "src/fit/revolution_test.h"

namespace polarform {

// A tolerance below this fraction of σ̂ is refused: σ̂ is measured along the rays, which overstates
// the noise normal to the surface by up to 1/cos of the angle between ray and normal.
constexpr double kNoiseRefusal = 0.8;

struct ModelChoiceOptions {
  RevolutionMode revolution = RevolutionMode::automatic;
  bool automatic_net = true;  // a net not given (size 0, no tolerance) is chosen by the data
};

struct ModelChoice {
  FunctionSpace space;         // rotational_space(...) when F is made rotational
  FunctionFitOptions options;  // with the chosen net
  NetSelection net;            // what the data chose (or the noise it showed, under a tolerance)
  RevolutionTest revolution;
};

// Throws InputError "tolerance … below the noise estimate …" when options.tolerance is below
// kNoiseRefusal times the noise estimate σ̂ of the data (one the GCV growth reached, not one the
// limits stopped at).
ModelChoice choose_model(const Samples& samples, const FunctionSpace& space,
                         const FunctionFitOptions& options, const ModelChoiceOptions& model);

}  // namespace polarform
