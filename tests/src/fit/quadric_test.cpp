// General-quadric fitting and classification (Bae 2002, §4.3, Table 4.1): all 17 types from their
// canonical equations in random rigid placement and scaling, the 12 that have real points also
// from point clouds sampled on them; the fit is exact for exact data and invariant under rigid
// motions; the frame rules and origins (4.3) / Appendix E.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "src/error.h"
#include "src/fit/local_frame.h"
#include "src/fit/quadric_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;
using T = QuadricType;

constexpr double a = 2.0, b = 3.0, c = 1.5;

// q1..q10 of a canonical form: x², y², z², xy, yz, zx, x, y, z, 1.
Quadric canonical(double x2, double y2, double z2, double x, double y, double z, double d) {
  Quadric q;
  q.q << x2, y2, z2, 0, 0, 0, x, y, z, d;
  return q;
}

struct Case {
  T type;
  Quadric q;
};

std::vector<Case> table() {
  const double A = 1 / (a * a), B = 1 / (b * b), C = 1 / (c * c);
  return {
      {T::real_ellipsoid, canonical(A, B, C, 0, 0, 0, -1)},
      {T::imaginary_ellipsoid, canonical(A, B, C, 0, 0, 0, 1)},
      {T::hyperboloid_of_one_sheet, canonical(A, B, -C, 0, 0, 0, -1)},
      {T::hyperboloid_of_two_sheets, canonical(A, B, -C, 0, 0, 0, 1)},
      {T::real_quadric_cone, canonical(A, B, -C, 0, 0, 0, 0)},
      {T::imaginary_quadric_cone, canonical(A, B, C, 0, 0, 0, 0)},
      {T::elliptic_paraboloid, canonical(A, B, 0, 0, 0, 2, 0)},
      {T::hyperbolic_paraboloid, canonical(A, -B, 0, 0, 0, 2, 0)},
      {T::real_elliptic_cylinder, canonical(A, B, 0, 0, 0, 0, -1)},
      {T::imaginary_elliptic_cylinder, canonical(A, B, 0, 0, 0, 0, 1)},
      {T::hyperbolic_cylinder, canonical(A, -B, 0, 0, 0, 0, -1)},
      {T::real_intersecting_planes, canonical(A, -B, 0, 0, 0, 0, 0)},
      {T::imaginary_intersecting_planes, canonical(A, B, 0, 0, 0, 0, 0)},
      {T::parabolic_cylinder, canonical(1, 0, 0, 0, 2, 0, 0)},
      {T::real_parallel_planes, canonical(1, 0, 0, 0, 0, 0, -1)},
      {T::imaginary_parallel_planes, canonical(1, 0, 0, 0, 0, 0, 1)},
      {T::coincident_planes, canonical(1, 0, 0, 0, 0, 0, 0)},
  };
}

// The quadric in coordinates x = R y + t (y canonical), coefficients scaled by s.
Quadric placed(const Quadric& q, const test::Rigid& m, double s) {
  Quadric g = q.substituted(m.R.transpose(), -m.R.transpose() * m.t);
  g.q *= s;
  return g;
}

TEST(QuadricClassification, AllSeventeenTypesOfTable41InAnyPlacement) {
  int seed = 100;
  for (const Case& k : table())
    for (double s : {1.0, -0.01, 250.0}) {
      const test::Rigid m = test::random_rigid(seed++, 30.0);
      const QuadricClassification cls = classify_quadric(placed(k.q, m, s), 10.0, 1e-9);
      EXPECT_EQ(cls.type, k.type) << to_string(k.type) << " classified as " << to_string(cls.type)
                                  << " (rank Qu " << cls.rank_Qu << ", rank Q " << cls.rank_Q << ")";
    }
  EXPECT_THROW(classify_quadric(Quadric{}, 1.0, 1e-9), InputError);
}

// Points on the real types, in canonical coordinates.
std::vector<std::pair<T, std::function<Eigen::Vector3d(std::mt19937&)>>> samplers() {
  using V = Eigen::Vector3d;
  auto U = [](std::mt19937& r, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(r); };
  return {
      {T::real_ellipsoid, [=](std::mt19937& r) { const double p = std::acos(U(r, -1, 1)), t = U(r, 0, 2 * kPi);
                                                  return V(a * std::sin(p) * std::cos(t), b * std::sin(p) * std::sin(t), c * std::cos(p)); }},
      {T::hyperboloid_of_one_sheet, [=](std::mt19937& r) { const double s = U(r, -1, 1), t = U(r, 0, 2 * kPi);
                                                            return V(a * std::cosh(s) * std::cos(t), b * std::cosh(s) * std::sin(t), c * std::sinh(s)); }},
      {T::hyperboloid_of_two_sheets, [=](std::mt19937& r) { const double s = U(r, 0, 1.2), t = U(r, 0, 2 * kPi), e = U(r, -1, 1) < 0 ? -1 : 1;
                                                             return V(a * std::sinh(s) * std::cos(t), b * std::sinh(s) * std::sin(t), e * c * std::cosh(s)); }},
      {T::real_quadric_cone, [=](std::mt19937& r) { const double s = U(r, -2, 2), t = U(r, 0, 2 * kPi);
                                                     return V(a * s * std::cos(t), b * s * std::sin(t), c * s); }},
      {T::elliptic_paraboloid, [=](std::mt19937& r) { const double s = U(r, 0, 2), t = U(r, 0, 2 * kPi);
                                                       return V(a * s * std::cos(t), b * s * std::sin(t), -s * s / 2); }},
      {T::hyperbolic_paraboloid, [=](std::mt19937& r) { const double x = U(r, -3, 3), y = U(r, -3, 3);
                                                         return V(x, y, -(x * x / (a * a) - y * y / (b * b)) / 2); }},
      {T::real_elliptic_cylinder, [=](std::mt19937& r) { const double t = U(r, 0, 2 * kPi);
                                                          return V(a * std::cos(t), b * std::sin(t), U(r, -3, 3)); }},
      {T::hyperbolic_cylinder, [=](std::mt19937& r) { const double s = U(r, -1.2, 1.2), e = U(r, -1, 1) < 0 ? -1 : 1;
                                                       return V(e * a * std::cosh(s), b * std::sinh(s), U(r, -3, 3)); }},
      {T::real_intersecting_planes, [=](std::mt19937& r) { const double x = U(r, -3, 3), e = U(r, -1, 1) < 0 ? -1 : 1;
                                                            return V(x, e * b / a * x, U(r, -3, 3)); }},
      {T::parabolic_cylinder, [=](std::mt19937& r) { const double x = U(r, -2, 2); return V(x, -x * x / 2, U(r, -3, 3)); }},
      {T::real_parallel_planes, [=](std::mt19937& r) { return V(U(r, -1, 1) < 0 ? -1 : 1, U(r, -3, 3), U(r, -3, 3)); }},
  };
}

TEST(QuadricFit, RecoversEveryRealTypeFromPoints) {
  int seed = 200;
  for (const auto& [type, sample] : samplers()) {
    std::mt19937 rng(seed);
    const test::Rigid m = test::random_rigid(seed++, 50.0);
    Eigen::Matrix3Xd p(3, 3000);
    for (int k = 0; k < 3000; ++k) p.col(k) = m(sample(rng));
    const QuadricFit f = fit_quadric(p);
    EXPECT_EQ(f.classification.type, type) << to_string(type) << " fitted as " << to_string(f.classification.type);
    EXPECT_LT(f.rms_distance, 1e-9) << to_string(type);
    for (int k = 0; k < 3000; k += 97) EXPECT_NEAR(f.quadric(p.col(k)) / f.quadric.gradient(p.col(k)).norm(), 0.0, 1e-8);
  }
}

TEST(QuadricFit, IsInvariantUnderRigidMotion) {
  Eigen::Matrix3Xd p = test::spherical_cloud([](double phi, double t) { return 10 + std::cos(phi) + 0.5 * std::sin(t); },
                                             5000, 0.2, 2.8, 0, 2 * kPi, 40);
  const test::Rigid m = test::random_rigid(41, 1000.0);
  const QuadricFit f = fit_quadric(p), g = fit_quadric(m(p));
  const Quadric back = placed(f.quadric, m, 1.0);  // f moved by m
  const double sign = back.q.dot(g.quadric.q) < 0 ? -1 : 1;
  EXPECT_LT((sign * back.q / back.q.norm() - g.quadric.q).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_NEAR(f.rms_distance, g.rms_distance, 1e-9);
  EXPECT_EQ(f.classification.type, g.classification.type);
}

TEST(LocalFrame, OriginsAndAxesFollowBae43AndAppendixE) {
  const test::Rigid m = test::random_rigid(42);
  // Ellipsoid: origin by (4.3) at the centre, k the largest eigenvalue = the shortest axis c.
  std::mt19937 rng(43);
  const auto smp = samplers();
  Eigen::Matrix3Xd e(3, 2000), cyl(3, 2000), hyp(3, 2000);
  for (int k = 0; k < 2000; ++k) {
    e.col(k) = m(smp[0].second(rng));
    hyp.col(k) = m(smp[1].second(rng));
    cyl.col(k) = m(smp[6].second(rng));
  }
  const FrameEstimate fe = estimate_frame(e);
  EXPECT_LT((fe.frame.origin - m.t).norm(), 1e-9);
  EXPECT_NEAR(std::abs(fe.frame.axes.col(2).dot(m.R.col(2))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(fe.frame.axes.col(0).dot(m.R.col(0))), 1.0, 1e-12);  // next: a < b
  // Hyperboloid of one sheet: k the lone negative eigenvalue's eigenvector, origin its centre.
  const FrameEstimate fh = estimate_frame(hyp);
  EXPECT_LT((fh.frame.origin - m.t).norm(), 1e-9);
  EXPECT_NEAR(std::abs(fh.frame.axes.col(2).dot(m.R.col(2))), 1.0, 1e-12);
  // Elliptic cylinder: rank 2, Appendix E puts the origin on the axis at the data's mean height.
  const FrameEstimate fc = estimate_frame(cyl);
  EXPECT_NEAR(std::abs(fc.frame.axes.col(2).dot(m.R.col(2))), 1.0, 1e-12);
  const Eigen::Vector3d mean = cyl.rowwise().mean();
  const Eigen::Vector3d k = m.R.col(2);
  EXPECT_LT((fc.frame.origin - (m.t + k * k.dot(mean - m.t))).norm(), 1e-9);
  // The frame is right-handed and orthonormal; user overrides win.
  EXPECT_LT((fc.frame.axes.transpose() * fc.frame.axes - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(fc.frame.axes.determinant(), 1.0, 1e-12);
  FrameOptions o;
  o.origin = Eigen::Vector3d(1, 2, 3);
  o.axis = Eigen::Vector3d(0, 0, 2);
  o.reference = Eigen::Vector3d(1, 1, 0);
  const FrameEstimate fu = estimate_frame(cyl, o);
  EXPECT_FALSE(fu.quadric);
  EXPECT_EQ(fu.frame.origin, Eigen::Vector3d(1, 2, 3));
  EXPECT_NEAR(fu.frame.axes(0, 0), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(fu.frame.axes(2, 2), 1.0, 1e-15);
  // Planes define no frame.
  Eigen::Matrix3Xd pl(3, 500);
  for (int k = 0; k < 500; ++k) pl.col(k) = m(smp[10].second(rng));
  EXPECT_THROW(estimate_frame(pl), InputError);
}

}  // namespace
}  // namespace polarform
