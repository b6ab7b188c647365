// The sparse normal equations of a weighted least-squares fit of a tensor-product B-spline
// function to scattered samples (Bae 2002, eqs. (C.3), (C.8a); Patrikalakis lecture 8, eq. (8.10)):
// A = Σ w_k B_k B_k^T and b = Σ w_k g_k B_k in the unknowns of a CoefficientMap, where B_k holds the
// (p+1)(q+1) non-zero basis products at (u_k, v_k). Assembled in O(points) time in banded
// per-thread accumulators (O(coefficients) memory, no dense intermediates), then folded.
#pragma once

#include <Eigen/SparseCore>
#include <cstddef>

#include "src/fit/coefficient_map.h"
#include "src/fit/parallel.h"
#include "src/fit/samples.h"
#include "src/fit/spline_axis.h"

namespace polarform {

struct NormalEquations {
  Eigen::SparseMatrix<double> A;  // symmetric, both triangles stored
  Eigen::VectorXd b;
  double gg = 0.0;                // Σ w g², for residuals from the normal equations
  double weight_sum = 0.0;
  std::size_t count = 0;
};

// Samples outside the axes' domains are evaluated at the clamped parameter.
NormalEquations assemble_normal_equations(const SplineAxis& u, const SplineAxis& v,
                                          const CoefficientMap& map, const Samples& samples,
                                          int threads = 1, ProgressRange progress = {});

}  // namespace polarform
