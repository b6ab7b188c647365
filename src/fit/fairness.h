// The fairness (thin-plate) energy of a single-valued B-spline function as a quadratic form in its
// unknowns: J(F) = ∫∫ F_ss² + 2 F_st² + F_tt² ds dt on the domain mapped to the unit square
// (s, t ∈ [0, 1]), i.e. the bending energy of Patrikalakis' lecture 8 (§8.2) written for a graph; a
// curve (1 x n surface, degree 0 along u) gets ∫ F_tt² dt. It regularises the least-squares fit so
// that holes in the data stay smooth instead of blowing up.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "src/fit/coefficient_map.h"
#include "src/fit/spline_axis.h"

namespace polarform {

// G_ij = ∫ N_i^(r)(s) N_j^(r)(s) ds over the axis domain mapped to [0, 1] (size() x size(), banded),
// by Gauss–Legendre quadrature exact for the integrand's degree.
Eigen::MatrixXd derivative_gram(const SplineAxis& axis, int order);

// The thin-plate energy matrix T in the unknowns of `map` (J = x^T T x): the Kronecker sum
// G2u⊗G0v + 2·G1u⊗G1v + G0u⊗G2v folded through the map, symmetric, with both triangles stored.
Eigen::SparseMatrix<double> thin_plate_matrix(const SplineAxis& u, const SplineAxis& v,
                                              const CoefficientMap& map);

}  // namespace polarform
