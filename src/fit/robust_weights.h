// Robust regression weights: Tukey's biweight (Beaton & Tukey 1974) with c = 4.685 on the scale
// 1.4826·MAD of the residuals (the normal-consistent median absolute deviation), floored.
#pragma once

#include <Eigen/Core>

namespace polarform {

// w_k = (1 − t²)² for |t| < 1, else 0, t = r_k / (4.685 · max(1.4826·MAD(r), floor)).
Eigen::VectorXd tukey_weights(const Eigen::VectorXd& residual, double floor);

}  // namespace polarform
