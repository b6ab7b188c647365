// Skinning (NURBS Book §10.3; spec B4): a surface through a sequence of section curves. The
// sections are rewritten on one basis (common_basis.h: degree elevation, union knots) and every
// homogeneous control point is interpolated across the sections by the cubic spline with knots at
// the section parameters (curve_interpolation.h), so S(u, v_k) = C_k(u) exactly.
#pragma once

#include <vector>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// Inputs: sections C_0 … C_{K−1} (K >= 2) on one parameter domain in u, and their parameters
// v_0 < … < v_{K−1}. Output: S of degree (max p_k, 3) on the sections' u domain and [v_0, v_{K−1}]
// in v, with Bessel end tangents in v (curve_interpolation.h) from three sections on, so that a
// bent run keeps its curvature to its end sections; two sections give a surface linear in v.
// Rational sections are blended homogeneously: S is their ruled or skinned surface exactly when
// their weight functions agree up to a constant factor. Throws InputError for fewer than two
// sections, a parameter count that differs, v not strictly increasing, or differing domains.
NurbsSurface skin_sections(const std::vector<NurbsCurve3d>& sections, const std::vector<double>& v);

}  // namespace polarform
