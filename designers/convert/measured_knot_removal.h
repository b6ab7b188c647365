// Knot removal on a converted profile within the error budget the conversion left: every interior
// knot copy of C is removed in the homogeneous space (NURBS Book A5.8), and the removal is kept
// only when the radial error against R, measured on the parameter range the removal changed, stays
// within the tolerance. The caller measures the whole result again.
#pragma once

#include <vector>

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct MeasuredRemoval {
  NurbsCurve2d curve;
  int removed = 0;  // knot copies removed
};

// Removes interior knot copies of C: first one copy of every knot where C is only C0 while the
// finely measured radial error of the changed range stays <= tol, then, left to right, as many
// copies of every knot as keep the quickly measured error <= `share` · tol (share in (0, 1]
// leaves a margin for the coarser sampling).
// Knots at the parameters `keep` are left as they are.
MeasuredRemoval remove_knots_within(const NurbsCurve2d& C, const PolarFunction& R, double tol,
                                    const std::vector<double>& keep = {}, double share = 0.95);

}  // namespace polarform
