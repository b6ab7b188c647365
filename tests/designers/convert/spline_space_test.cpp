// The spline spaces of the degree-limited fit: a mirrored space's curve is its own mirror image in
// the line at its last break's polar angle, with the control values and the knot (or none) at the
// line that the space says; point() agrees with the exported curve on the sampled half.
#include "designers/convert/spline_space.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/nurbs/periodic.h"

namespace polarform {
namespace {

// The distinct control values of a space, pseudo-random but for a middle one on the mirror line.
Eigen::MatrixXd values_of(const SplineSpace& s) {
  Eigen::MatrixXd coefs(2, s.size());
  for (int j = 0; j < s.size(); ++j)
    coefs.col(j) = Eigen::Vector2d(40 + 7 * std::sin(1.7 * j), 25 + 9 * std::cos(2.3 * j));
  if (s.middle_on_mirror_line()) {
    const double b = s.breaks().back();
    coefs.col(s.size() - 1) = 55 * Eigen::Vector2d(std::cos(b), std::sin(b));
  }
  return coefs;
}

TEST(SplineSpace, AMirroredCurveIsItsOwnMirrorImage) {
  const std::vector<double> breaks = {0.1, 0.4, 0.9, 1.2};  // b = 1.2 rad: the line's angle
  const double a = breaks.front(), b = breaks.back();
  Eigen::Matrix2d S;  // the reflection in the line at angle b
  S << std::cos(2 * b), std::sin(2 * b), std::sin(2 * b), -std::cos(2 * b);
  for (int p : {2, 3, 4, 5})
    for (Ends ends : {Ends::mirrored, Ends::mirrored_smooth}) {
      SCOPED_TRACE("degree " + std::to_string(p) + (ends == Ends::mirrored ? "" : ", smooth"));
      const SplineSpace s(p, ends, breaks);
      const Eigen::MatrixXd coefs = values_of(s);
      const NurbsCurve2d C = s.curve(coefs);
      // 3 spans and their images, sharing the one across the line when it is smooth.
      const int spans = ends == Ends::mirrored ? 6 : 5;
      EXPECT_EQ(C.size(), spans + p);
      EXPECT_EQ(s.size(), (spans + p + 1) / 2);
      EXPECT_EQ(s.middle_on_mirror_line(), (spans + p) % 2 == 1);
      EXPECT_DOUBLE_EQ(C.front(), a);
      EXPECT_DOUBLE_EQ(C.back(), 2 * b - a);
      EXPECT_EQ(std::count(C.knots().begin(), C.knots().end(), b), ends == Ends::mirrored ? 1 : 0);
      for (int k = 0; k <= 100; ++k) {
        const double u = a + (b - a) * k / 100;
        const Eigen::Vector2d image = S * C(u);
        EXPECT_NEAR((C(2 * b - u) - image).norm(), 0.0, 1e-12);
        EXPECT_NEAR((s.point(coefs, u) - C(u)).norm(), 0.0, 1e-12);
      }
    }
}

TEST(SplineSpace, MirroredValuesFoldBackPastTheMiddle) {
  // Degree 3 on 2 spans and their images: 7 control values, 4 distinct, the middle one on the line.
  const SplineSpace s(3, Ends::mirrored, {0.0, 0.5, 1.0});
  ASSERT_EQ(s.size(), 4);
  const int value[7] = {0, 1, 2, 3, 2, 1, 0};
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(s.value(k), value[k]) << k;
    EXPECT_EQ(s.reflected(k), k > 3) << k;
  }
  EXPECT_TRUE(s.middle_on_mirror_line());
}

// A periodic space with a seam knot of multiplicity m: k + m − 1 distinct control values, the
// clamped curve's k + p, and C^(p−m) across the seam; with m = 1 the curve is Bae's periodic
// B-spline (eq. 3.9-3.10) clipped to [a, b].
TEST(SplineSpace, APeriodicSpacesSeamKnotSetsItsContinuityThere) {
  const std::vector<double> breaks = {0.0, 1.0, 2.5, 4.0, 5.0, 5.7, 2 * std::numbers::pi};
  for (int p : {3, 4, 5})
    for (int m = 1; m <= p; ++m) {
      SCOPED_TRACE("degree " + std::to_string(p) + ", seam multiplicity " + std::to_string(m));
      const SplineSpace s(p, Ends::periodic, breaks, {.seam = m, .interior = {}});
      ASSERT_EQ(s.size(), 6 + m - 1);
      Eigen::MatrixXd coefs(2, s.size());
      for (int j = 0; j < s.size(); ++j)
        coefs.col(j) = Eigen::Vector2d(40 * std::cos(1.1 * j) + 3 * j, 30 * std::sin(0.7 * j));
      const NurbsCurve2d C = s.curve(coefs);
      EXPECT_EQ(C.size(), 6 + p);
      const auto start = C.derivatives(C.front(), p), end = C.derivatives(C.back(), p);
      for (int k = 0; k <= p - m; ++k)
        EXPECT_LE((start[k] - end[k]).norm(), 1e-9 * std::max(1.0, start[k].norm())) << k;
      EXPECT_GT((start[p - m + 1] - end[p - m + 1]).norm(), 1e-3) << p - m + 1;
      for (int i = 0; i <= 50; ++i) {
        const double t = breaks.back() * i / 50;
        EXPECT_NEAR((s.point(coefs, t) - C(t)).norm(), 0.0, 1e-9);
        if (m == 1) {
          const BSpline bae = clip(periodic_bspline(p, breaks, coefs), 0.0, breaks.back());
          double xy[2];
          bae.point(t, xy);
          EXPECT_NEAR((C(t) - Eigen::Vector2d(xy[0], xy[1])).norm(), 0.0, 1e-9);
        }
      }
    }
}

// An interior knot of multiplicity m: m − 1 more control values, C^(p−m) there; in a mirrored
// space at the break's mirror image too.
TEST(SplineSpace, AnInteriorKnotsMultiplicitySetsItsContinuityThere) {
  const std::vector<double> breaks = {0.1, 0.4, 0.9, 1.2};
  for (Ends ends : {Ends::clamped, Ends::periodic, Ends::mirrored})
    for (int p : {3, 5})
      for (int m = 1; m <= p; ++m) {
        SCOPED_TRACE("ends " + std::to_string(static_cast<int>(ends)) + ", degree " +
                     std::to_string(p) + ", multiplicity " + std::to_string(m));
        const std::vector<double> b =
            ends == Ends::periodic ? std::vector<double>{0.0, 0.4, 0.9, 2.0, 3.0, 4.0, 5.0, 6.0}
                                   : breaks;
        const SplineSpace s(p, ends, b, {1, {{0.4, m}}});
        const Eigen::MatrixXd coefs = values_of(s);
        const NurbsCurve2d C = s.curve(coefs);
        const int spans = ends == Ends::mirrored ? 6 : static_cast<int>(b.size()) - 1;
        const int extra = (ends == Ends::mirrored ? 2 : 1) * (m - 1);
        EXPECT_EQ(C.size(), spans + p + extra);
        const std::vector<double> at = ends == Ends::mirrored
                                           ? std::vector<double>{0.4, 2 * 1.2 - 0.4}
                                           : std::vector<double>{0.4};
        for (double u : at) {
          const double h = 1e-9;
          const auto left = C.derivatives(u - h, p), right = C.derivatives(u + h, p);
          for (int k = 0; k <= p - m; ++k)
            EXPECT_LE((left[k] - right[k]).norm(), 1e-5 * std::max(1.0, left[k].norm())) << k;
          EXPECT_GT((left[p - m + 1] - right[p - m + 1]).norm(), 1e-3) << p - m + 1;
        }
        for (int i = 0; i <= 50; ++i) {
          const double t = b.front() + (b.back() - b.front()) * i / 50;
          EXPECT_NEAR((s.point(coefs, t) - C(t)).norm(), 0.0, 1e-9);
        }
      }
}

TEST(SplineSpace, ClampedAndPeriodicSpacesKeepTheirCounts) {
  const std::vector<double> breaks = {0.0, 1.0, 2.5, 4.0, 5.0, 2 * 3.141592653589793};
  const SplineSpace clamped(3, Ends::clamped, breaks), periodic(3, Ends::periodic, breaks);
  EXPECT_EQ(clamped.size(), 5 + 3);
  EXPECT_EQ(periodic.size(), 5);
  EXPECT_EQ(periodic.value(6), 1);
  EXPECT_FALSE(clamped.reflected(7));
  EXPECT_EQ(clamped.curve(Eigen::MatrixXd::Ones(2, 8)).size(), 8);
  EXPECT_EQ(periodic.curve(Eigen::MatrixXd::Ones(2, 5)).size(), 5 + 3);
}

}  // namespace
}  // namespace polarform
