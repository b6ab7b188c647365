// Solving the fairness-regularised normal equations (A/W + λT) x = b/W, W = Σ w (the weighted mean
// squared residual plus λ times the thin-plate energy, Patrikalakis lecture 8, §8.1–8.2) by a
// sparse LDL^T factorisation, with λ fixed, relative to the data term, or chosen by generalized
// cross-validation (Craven & Wahba 1979) for noisy data.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "src/fit/normal_equations.h"

namespace polarform {

struct FairnessOptions {
  enum class Mode {
    fixed,     // λ = weight
    relative,  // λ = weight · (tr(A)/W) / tr(T): scale-free, touches only what the data leaves free
    gcv,       // λ minimising GCV(λ) = (RSS/W) / (1 − tr(H)/n)²; weight is ignored
  };
  Mode mode = Mode::relative;
  double weight = 1e-7;
  // Rademacher probes of the Hutchinson estimate of tr(H) (fixed seed: repeatable).
  int gcv_probes = 16;
};

struct RegularisedSolution {
  Eigen::VectorXd x;
  double lambda = 0.0;
  double rss = 0.0;    // Σ w (F(u_k, v_k) − g_k)², from the normal equations
  double dof = -1.0;   // tr(H), the effective number of parameters (gcv mode only)
  double gcv = -1.0;   // the criterion at the chosen λ (gcv mode only)
};

// Throws InputError for a bad weight or mismatched sizes, NumericalError (with the smallest pivot
// ratio) when the system is singular to working precision, e.g. λ = 0 with control values that no
// sample touches.
RegularisedSolution solve_regularised(const NormalEquations& ne, const Eigen::SparseMatrix<double>& T,
                                      const FairnessOptions& options);

}  // namespace polarform
