// The cross-boundary derivative curves of a bicubically blended Coons base surface fitted to data
// (Piegl & Tiller 2001, §2.2; spec P2): the patch is affine in the derivative curves' control
// points, their end points are the boundary tangents (eliminated), the four corner twists agree
// (linear constraints), and the rest is least squares on the points — solved by the null space of
// the constraints (constrained_least_squares).
#pragma once

#include <Eigen/Core>

#include "src/nurbs/coons_surface.h"

namespace polarform {

struct BicubicCoonsFitOptions {
  // Scale each fitted derivative curve against overshoot (P&T after Fig. 2): D̂ = (L/(L_u+L_v))·
  // (L/mag)·D with L the mean length of the curves it points along; breaks twist compatibility.
  bool scale_cross_derivatives = false;
};

struct BicubicCoonsFit {
  NurbsSurface surface;         // bicubic_coons(boundary, derivatives)
  CrossDerivatives derivatives;
  double twist_mismatch = 0.0;  // max over corners of |S_uv from D_k' − S_uv from D_l'| (mm)
};

// points (3 × N) with parameters u, v in [0, 1] (e.g. from the bilinear base); needs enough points
// for the unknowns (else InputError with both counts).
BicubicCoonsFit fit_bicubic_coons(const PatchBoundary& boundary, const Eigen::Matrix3Xd& points,
                                  const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                  const BicubicCoonsFitOptions& options = {});

}  // namespace polarform
