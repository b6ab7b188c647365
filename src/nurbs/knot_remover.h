// KnotRemover: the engine behind every knot removal when several knots go from one B-spline. Each
// copy of a knot goes by the equations of NURBS Book A5.8 (Tiller's removal), solved from both ends
// with the split chosen where the recursions do not amplify round-off, so removal stays exact next
// to nearly coincident knots. One working copy is edited and compacted lazily (a gap buffer that
// moves right with the removals): removing k knots left to right costs O(n + k·p) column moves.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/bspline.h"

namespace polarform {

class KnotRemover {
 public:
  // point_dim: rows per point for the removal test; the deviation of a removal is the largest
  // Euclidean norm over the row blocks of that size (a surface seen along one direction has dim·n
  // rows, i.e. n points of dim rows). coefs.rows() must be a multiple of it.
  KnotRemover(int degree, Knots knots, Eigen::MatrixXd coefs, int point_dim);

  struct Outcome {
    int removed;               // how many copies of the knot went
    double refused_deviation;  // the deviation that refused the next copy (0 if none was refused)
  };
  // Removes the interior knot u up to `times` times (at most its multiplicity). A copy goes when
  // its deviation — the residual of the one removal equation left unused, by which the B-spline
  // changes at most (times one basis function) — is <= tol. Throws InputError if u is not an
  // interior knot.
  Outcome remove(double u, int times, double tol);

  // Current multiplicity of u (0 if u is not a knot).
  int multiplicity(double u);

  // The B-spline after the removals; the remover is spent.
  BSpline finish() &&;

 private:
  int logical_knots() const { return static_cast<int>(U_.size()) - u_gap_size_; }
  int logical_coefs() const { return static_cast<int>(P_.cols()) - p_gap_size_; }
  // Make logical knots / coefficient columns [0, end) contiguous at the front of the buffers.
  void expose_knots(int end);
  void expose_coefs(int end);
  // Expose knots until the exposed part ends past every copy of u.
  void expose_knots_past(double u);
  // Removes the copy of u at knot index r (multiplicity s) if its deviation is <= tol; returns
  // the deviation.
  double remove_one(double u, int r, int s, double tol);
  double deviation(const double* a, const double* b) const;

  int p_;
  int point_dim_;
  double front_, back_;
  Knots U_;
  int u_gap_ = 0, u_gap_size_ = 0;  // logical knot i lives at U_[i] if i < u_gap_, else further on
  Eigen::MatrixXd P_;
  int p_gap_ = 0, p_gap_size_ = 0;
  Eigen::MatrixXd temp_;  // the new coefficients P'_{first-1} .. P'_{last}
  Eigen::VectorXd fit_;   // the unused equation's right-hand side
  std::vector<double> alpha_, grow_left_, grow_right_;
};

}  // namespace polarform
