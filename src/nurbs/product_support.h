// Building blocks shared by the curve and surface symbolic products: the Bezier product weights
// (Bae 2002, eq. (A.11)), the row-map checks, and the exact removal that takes a full-multiplicity
// product (A.8) down to the knots of (A.7).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/bspline.h"

namespace polarform::product_support {

// w(l, m) = C(p, l)·C(q, m) / C(p + q, l + m): h_k = sum_{l+m=k} w(l, m) f_l g_m (eq. (A.11)).
Eigen::MatrixXd bezier_product_weights(int p, int q);

// Distinct values of a knot vector.
std::vector<double> break_values(const Knots& knots);

// The full-multiplicity knot vector (A.8) of degree d on the breaks: ends d+1, interior d.
Knots full_multiplicity_knots(int d, const std::vector<double>& breaks);

// Throws InputError unless factor_rows and g_rows have the same positive length and index rows of
// factors (factor_dim rows) and g (g_dim rows).
void check_row_maps(const std::vector<int>& factor_rows, int factor_dim,
                    const std::vector<int>& g_rows, int g_dim, const char* what);

// Removes from the degree-d B-spline (full_knots, coefs) every knot copy that `target` does not
// have (target ⊂ full_knots, same breaks). The product is exact, so every removal must succeed at
// round-off; throws NumericalError with the numbers otherwise. point_dim as in KnotRemover.
BSpline remove_to_knots(int d, Knots full_knots, Eigen::MatrixXd coefs, const Knots& target,
                        int point_dim, const char* what);

}  // namespace polarform::product_support
