#include "src/nurbs/knot_remover.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

KnotRemover::KnotRemover(int degree, Knots knots, Eigen::MatrixXd coefs, int point_dim)
    : p_(degree),
      point_dim_(point_dim),
      U_(std::move(knots)),
      P_(std::move(coefs)),
      temp_(P_.rows(), degree + 2),
      fit_(P_.rows()),
      alpha_(degree + 1),
      grow_left_(degree + 2),
      grow_right_(degree + 2) {
  if (point_dim_ < 1 || P_.rows() % point_dim_ != 0)
    throw InputError("knot removal: point dimension " + std::to_string(point_dim_) +
                     " does not divide the coefficient dimension " + std::to_string(P_.rows()));
  front_ = U_[p_];
  back_ = U_[P_.cols()];
}

void KnotRemover::expose_knots(int end) {
  end = std::min(end, logical_knots());
  if (u_gap_size_ == 0) {
    u_gap_ = std::max(u_gap_, end);
    return;
  }
  for (; u_gap_ < end; ++u_gap_) U_[u_gap_] = U_[u_gap_ + u_gap_size_];
}

void KnotRemover::expose_coefs(int end) {
  end = std::min(end, logical_coefs());
  if (p_gap_size_ == 0) {
    p_gap_ = std::max(p_gap_, end);
    return;
  }
  for (; p_gap_ < end; ++p_gap_) P_.col(p_gap_) = P_.col(p_gap_ + p_gap_size_);
}

void KnotRemover::expose_knots_past(double u) {
  const int L = logical_knots();
  while (u_gap_ < L && (u_gap_ == 0 || U_[u_gap_ - 1] <= u)) expose_knots(u_gap_ + 1);
}

double KnotRemover::deviation(const double* a, const double* b) const {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < P_.rows(); i += point_dim_) {
    double sq = 0.0;
    for (int k = 0; k < point_dim_; ++k) sq += (a[i + k] - b[i + k]) * (a[i + k] - b[i + k]);
    worst = std::max(worst, sq);
  }
  return std::sqrt(worst);
}

int KnotRemover::multiplicity(double u) {
  expose_knots_past(u);
  const auto lo = std::lower_bound(U_.begin(), U_.begin() + u_gap_, u);
  const auto hi = std::upper_bound(lo, U_.begin() + u_gap_, u);
  return static_cast<int>(hi - lo);
}

// One copy of u by the removal equations of NURBS Book A5.8 (eq. (5.28)): with first = r - p and
// last = r - s, the old coefficients are P_i = α_i P'_i + (1 - α_i) P'_{i-1} for i in
// [first, last], α_i = (u - U_i) / (U_{i+p+1} - U_i), P'_{first-1} = P_{first-1} and
// P'_last = P_{last+1}. Equations i < m are solved left to right, i > m right to left, and the
// residual of equation m is the deviation. m minimises the round-off growth of both recursions.
double KnotRemover::remove_one(double u, int r, int s, double tol) {
  const int p = p_, first = r - p, last = r - s;
  expose_knots(last + p + 2);
  expose_coefs(last + 2);
  const double* U = U_.data();
  const int eqs = last - first + 1;  // 0 when s = p + 1 (a discontinuity)
  for (int k = 0; k < eqs; ++k) {
    const int i = first + k;
    alpha_[k] = (u - U[i]) / (U[i + p + 1] - U[i]);
  }
  // Error growth of P'_i from the left (index i - first + 1) and from the right (index i - first).
  grow_left_[0] = 0.0;
  for (int k = 0; k < eqs; ++k)
    grow_left_[k + 1] = ((1.0 - alpha_[k]) * grow_left_[k] + 1.0) / alpha_[k];
  grow_right_[eqs] = 0.0;
  for (int k = eqs - 1; k >= 0; --k)
    grow_right_[k] = (alpha_[k] * grow_right_[k + 1] + 1.0) / (1.0 - alpha_[k]);
  int m = 0;  // the unused equation, as an offset from first
  double best = INFINITY;
  for (int k = 0; k < eqs; ++k) {
    // P'_first .. P'_{first+k-1} from the left, P'_{first+k} .. P'_{last-1} from the right.
    double worst = 0.0;
    for (int j = 1; j <= k; ++j) worst = std::max(worst, grow_left_[j]);
    for (int j = k + 1; j < eqs; ++j) worst = std::max(worst, grow_right_[j]);
    if (worst < best) best = worst, m = k;
  }

  double dev;
  if (eqs == 0) {  // the two sides of a discontinuity must meet
    dev = deviation(P_.col(first - 1).data(), P_.col(first).data());
  } else {
    temp_.col(0) = P_.col(first - 1);
    temp_.col(eqs) = P_.col(last + 1);
    for (int k = 0; k < m; ++k)
      temp_.col(k + 1) = (P_.col(first + k) - (1.0 - alpha_[k]) * temp_.col(k)) / alpha_[k];
    for (int k = eqs - 1; k > m; --k)
      temp_.col(k) = (P_.col(first + k) - alpha_[k] * temp_.col(k + 1)) / (1.0 - alpha_[k]);
    fit_ = alpha_[m] * temp_.col(m + 1) + (1.0 - alpha_[m]) * temp_.col(m);
    dev = deviation(P_.col(first + m).data(), fit_.data());
  }
  if (dev > tol) return dev;

  for (int k = 1; k < eqs; ++k) P_.col(first + k - 1) = temp_.col(k);
  for (int i = last + 1; i < p_gap_; ++i) P_.col(i - 1) = P_.col(i);  // drop column last
  --p_gap_;
  ++p_gap_size_;
  for (int i = r + 1; i < u_gap_; ++i) U_[i - 1] = U_[i];  // drop knot r
  --u_gap_;
  ++u_gap_size_;
  return dev;
}

KnotRemover::Outcome KnotRemover::remove(double u, int times, double tol) {
  if (!(u > front_ && u < back_))
    throw InputError("knot removal: u = " + to_text(u) + " is not inside the domain (" +
                     to_text(front_) + ", " + to_text(back_) + ")");
  int s = multiplicity(u);
  if (s == 0) throw InputError("knot removal: u = " + to_text(u) + " is not a knot");
  const auto last_copy = std::upper_bound(U_.begin(), U_.begin() + u_gap_, u) - 1;
  const int r = static_cast<int>(last_copy - U_.begin());
  const int num = std::min(times, s);
  for (int t = 0; t < num; ++t, --s) {
    const double dev = remove_one(u, r - t, s, tol);
    if (dev > tol) return {t, dev};
  }
  return {num, 0.0};
}

BSpline KnotRemover::finish() && {
  expose_knots(logical_knots());
  expose_coefs(logical_coefs());
  U_.resize(logical_knots());
  const int n = logical_coefs();
  return BSpline(p_, std::move(U_), P_.leftCols(n));
}

}  // namespace polarform
