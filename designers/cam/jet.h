// Jet: a quantity with its exact derivatives 0..order (order <= 4) with respect to one parameter,
// and the arithmetic that propagates them (Leibniz rule, reciprocal and square-root recurrences).
// The cam geometry composes follower and rotation formulas with it, so every curve point, polar
// angle and curvature comes with exact derivatives instead of finite differences.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace polarform {

class Jet {
 public:
  static constexpr int kMaxOrder = 4;

  Jet() = default;
  // A constant known to derivative order `order`.
  Jet(double value, int order) : order_(order) { d_[0] = value; }
  // From value and derivatives d[0..order].
  static Jet from(const double* d, int order);

  int order() const { return order_; }
  double operator[](int k) const { return d_[k]; }
  double& operator[](int k) { return d_[k]; }
  // The derivative as a jet of one order less.
  Jet derivative() const;

  friend Jet operator+(const Jet& a, const Jet& b);
  friend Jet operator-(const Jet& a, const Jet& b);
  friend Jet operator*(const Jet& a, const Jet& b);
  friend Jet operator/(const Jet& a, const Jet& b);
  friend Jet operator+(const Jet& a, double c);
  friend Jet operator*(double c, const Jet& a);
  friend Jet sqrt(const Jet& a);

 private:
  std::array<double, kMaxOrder + 1> d_{};
  int order_ = 0;
};

namespace jet_detail {

inline constexpr double kBinomial[Jet::kMaxOrder + 1][Jet::kMaxOrder + 1] = {
    {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};

}  // namespace jet_detail

inline Jet Jet::from(const double* d, int order) {
  Jet j(d[0], order);
  for (int k = 1; k <= order; ++k) j.d_[k] = d[k];
  return j;
}

inline Jet Jet::derivative() const {
  Jet j(0.0, std::max(order_ - 1, 0));
  for (int k = 0; k < order_; ++k) j.d_[k] = d_[k + 1];
  return j;
}

inline Jet operator+(const Jet& a, const Jet& b) {
  Jet r(0.0, std::min(a.order_, b.order_));
  for (int k = 0; k <= r.order_; ++k) r.d_[k] = a.d_[k] + b.d_[k];
  return r;
}

inline Jet operator-(const Jet& a, const Jet& b) {
  Jet r(0.0, std::min(a.order_, b.order_));
  for (int k = 0; k <= r.order_; ++k) r.d_[k] = a.d_[k] - b.d_[k];
  return r;
}

inline Jet operator+(const Jet& a, double c) {
  Jet r = a;
  r.d_[0] += c;
  return r;
}

inline Jet operator*(double c, const Jet& a) {
  Jet r = a;
  for (int k = 0; k <= r.order_; ++k) r.d_[k] *= c;
  return r;
}

// Leibniz rule: (ab)^(k) = sum_i C(k,i) a^(i) b^(k-i).
inline Jet operator*(const Jet& a, const Jet& b) {
  Jet r(0.0, std::min(a.order_, b.order_));
  for (int k = 0; k <= r.order_; ++k) {
    double sum = 0.0;
    for (int i = 0; i <= k; ++i) sum += jet_detail::kBinomial[k][i] * a.d_[i] * b.d_[k - i];
    r.d_[k] = sum;
  }
  return r;
}

// q = a/b from Leibniz on q b = a: q^(k) = (a^(k) - sum_{i<k} C(k,i) q^(i) b^(k-i)) / b.
inline Jet operator/(const Jet& a, const Jet& b) {
  Jet q(0.0, std::min(a.order_, b.order_));
  for (int k = 0; k <= q.order_; ++k) {
    double sum = a.d_[k];
    for (int i = 0; i < k; ++i) sum -= jet_detail::kBinomial[k][i] * q.d_[i] * b.d_[k - i];
    q.d_[k] = sum / b.d_[0];
  }
  return q;
}

// h = sqrt(a) from Leibniz on h h = a: 2 h h^(k) = a^(k) - sum_{0<i<k} C(k,i) h^(i) h^(k-i).
inline Jet sqrt(const Jet& a) {
  Jet h(std::sqrt(a.d_[0]), a.order_);
  for (int k = 1; k <= h.order_; ++k) {
    double sum = a.d_[k];
    for (int i = 1; i < k; ++i) sum -= jet_detail::kBinomial[k][i] * h.d_[i] * h.d_[k - i];
    h.d_[k] = sum / (2.0 * h.d_[0]);
  }
  return h;
}

}  // namespace polarform
