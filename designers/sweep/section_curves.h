// The sections of a section sweep fitted as compatible closed curves (Kantz 2003, §5.4; spec K12
// step 3): each section, star-shaped about a centre (given: the spine; or its algebraic circle
// fit), is a polar curve C(u) = c + F(u)·B(u) (Bae 2002, eq. (2.10)) on ONE base circle B — four
// RQB arcs starting at θ = 0, the section frame's x direction, counter-clockwise — and F on one
// periodic knot vector. The curves then share degree, knots and weights: compatible for skinning,
// and their start points correspond. A circle is fitted exactly (F reduces to a constant). A slab's
// points lie on either side of its station: r is fitted as F(u) + a·G(u) (linear in the offset a
// along the spine, Bae 2002 (3.8)'s tensor-product fit of degree 1 in a), and F is the section at a
// = 0, so a section that changes along the spine is not smeared by its slab.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "src/base/base_circle.h"
#include "src/fit/error_stats.h"
#include "src/nurbs/bspline.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct SectionCurveOptions {
  int degree = 3;
  double tolerance = 0.0;  // max radial residual asked for (> 0)
  int min_points = 24;     // per section
  // The polar centre of every section (the spine's point, the origin of the station frames): one
  // centre keeps the sections' angles, and so their parameters, in correspondence. Absent: each
  // section's algebraic circle fit (Taubin), which wanders with the sampling of a non-circle.
  std::optional<Eigen::Vector2d> centre;
  double max_gap = 1.0471975511965976;  // 60°: the largest angular gap a closed section may have
  int threads = 2;
};

struct SectionCurve {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();    // of the polar fit
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // of the area the curve bounds
  BSplineFunction F;                                   // on the common knot vector
  NurbsCurve2d curve;                                  // c + F·B
  ErrorStats error;          // radial residuals of the slab's points to F + a·G
  double mean_radius = 0.0;  // mean of F over the angle
};

struct SectionCurves {
  BaseCircle base;
  int size = 0;  // the common number of F's spans
  std::vector<SectionCurve> sections;
};

// The common base circle: four RQB arcs over [0, 2π].
BaseCircle section_base_circle();

// A slab: its points' (x, y) in the station frame and their offsets along the spine from the
// station, in [−1, 1] (units of the slab's half-width).
struct SectionSlab {
  Eigen::Matrix2Xd points;
  Eigen::VectorXd along;
};

// One section on `size` periodic spans of the base. Throws InputError naming `where` for fewer
// than min_points points, a gap wider than max_gap about the centre (not closed) or rays from the
// centre crossing the points twice (not star-shaped).
SectionCurve fit_section_curve(const SectionSlab& slab, const BaseCircle& base, int size,
                               const SectionCurveOptions& options, const std::string& where);

// All sections on the smallest common size (4, 8, 12, … spans, at most 64) at which every
// section's radial residual meets the tolerance, or beyond which the residuals' σ per degree of
// freedom falls by less than 1 % (the noise floor), then rewritten on one basis (common_basis.h).
// Throws as fit_section_curve; where[k] names section k.
SectionCurves fit_section_curves(const std::vector<SectionSlab>& sections,
                                 const SectionCurveOptions& options,
                                 const std::vector<std::string>& where);

}  // namespace polarform
