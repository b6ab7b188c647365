// A meridian function r(z) of a surface of revolution for the axis refinement of rotation_axis.h: a
// least-squares cubic B-spline on uniform knots over the data's z range (function_fit.h), its
// size chosen once by GCV (Craven & Wahba 1979), refitted to the meridian points every
// Gauss–Newton iteration; the residual of (z, r) is r − f(z) times the cosine of the profile's
// slope (the distance to the curve to first order), signed along its normal (−f', 1)/√(1 + f'²).
#pragma once

#include <Eigen/Core>
#include <string>

#include "src/fit/rotation_axis.h"
#include "src/nurbs/bspline.h"

namespace polarform {

struct MeridianFunction {
  BSplineFunction r;  // r(z) on [z0, z1]
  double rms = 0.0;   // of r_k − f(z_k)
  double gcv = 0.0;
};

// The least-squares cubic r(z) with `size` coefficients on uniform knots over the z range of zr
// (2 x n: z, r) by fit_curve_function; spans without data are held by its relative fairing.
MeridianFunction fit_meridian_function(const Eigen::Matrix2Xd& zr, int size);

// The profile size by GCV: sizes from 6 grown by half again, stopping after two sizes without a 1 %
// gain, at n / 4 coefficients or at `max_size`.
int choose_meridian_function_size(const Eigen::Matrix2Xd& zr, int max_size = 160);

// The model refine_axis_by_profile needs: fit_meridian_function(zr, size) at every call.
MeridianModel meridian_function_model(int size);

}  // namespace polarform
