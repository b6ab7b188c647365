// Jet: a quantity with its exact derivatives 0..order (order <= 4) with respect to one parameter,
// and the arithmetic that propagates them (Leibniz rule, reciprocal and square-root recurrences,
// Faà di Bruno's formula for sine and cosine).
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
  friend Jet sin(const Jet& a);
  friend Jet cos(const Jet& a);

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

namespace jet_detail {

// f(a) from f, f', ..., f'''' at a's value by Faà di Bruno's formula (orders <= 4).
inline Jet compose(const double* f, const Jet& a) {
  Jet h(f[0], a.order());
  const double g1 = a.order() >= 1 ? a[1] : 0, g2 = a.order() >= 2 ? a[2] : 0;
  const double g3 = a.order() >= 3 ? a[3] : 0, g4 = a.order() >= 4 ? a[4] : 0;
  const double d[5] = {f[0], f[1] * g1, f[2] * g1 * g1 + f[1] * g2,
                       f[3] * g1 * g1 * g1 + 3 * f[2] * g1 * g2 + f[1] * g3,
                       f[4] * g1 * g1 * g1 * g1 + 6 * f[3] * g1 * g1 * g2 +
                           f[2] * (3 * g2 * g2 + 4 * g1 * g3) + f[1] * g4};
  for (int k = 1; k <= a.order(); ++k) h[k] = d[k];
  return h;
}

}  // namespace jet_detail

inline Jet sin(const Jet& a) {
  const double s = std::sin(a.d_[0]), c = std::cos(a.d_[0]);
  const double f[5] = {s, c, -s, -c, s};
  return jet_detail::compose(f, a);
}

inline Jet cos(const Jet& a) {
  const double s = std::sin(a.d_[0]), c = std::cos(a.d_[0]);
  const double f[5] = {c, -s, -c, s, c};
  return jet_detail::compose(f, a);
}

}  // namespace polarform
