// The converter (Bae 2002, §5.1): for every example cam and tolerances 1e-2..1e-6 mm the
// measured radial error — checked here by independent dense sampling of the final NURBS — meets
// the tolerance; constant R gives an exact circle of degree 2 (RQB) / 4 (quartic); the curve is
// the product C(u) = F(u)·B̃(u); polynomial laws are represented exactly.
#include "designers/convert/polar_conversion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "designers/cam/contour_polar_function.h"
#include "designers/cam/displacement_polar_function.h"
#include "tests/support/designers/example_cams.h"
#include "tests/support/designers/mirror_symmetric_profile.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

PolarFunction example_contour(const char* name) {
  return cam_polar_function(make_plate_cam(test::example_cam_design(name)));
}

// Independent check: the final NURBS at n uniform parameters against R at each point's own
// polar angle.
double dense_radial_error(const NurbsCurve2d& C, const PolarFunction& R, int n) {
  double worst = 0;
  for (int k = 0; k <= n; ++k) {
    const double u = C.front() + (C.back() - C.front()) * k / n;
    const Eigen::Vector2d p = C(u);
    double psi = std::atan2(p.y(), p.x());
    while (psi < R.start) psi += 2 * kPi;
    while (psi > R.end) psi -= 2 * kPi;
    worst = std::max(worst, std::abs(p.norm() - R(psi)));
  }
  return worst;
}

class ExampleConversion : public testing::TestWithParam<const char*> {};

TEST_P(ExampleConversion, MeasuredErrorMeetsEveryTolerance) {
  const PolarFunction R = example_contour(GetParam());
  for (double tol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    ConversionOptions options;
    options.tolerance = tol;
    const PolarConversion c = convert_polar_function(R, options);
    const double dense = dense_radial_error(c.curve, R, 60000);
    EXPECT_LE(dense, tol) << GetParam() << " at " << tol;
    EXPECT_LE(c.max_radial_error, tol);
    // The converter's own measurement agrees with the dense one (it refines the maxima).
    EXPECT_GE(c.max_radial_error, 0.99 * dense);
    EXPECT_LE(c.max_normal_error, c.max_radial_error);
    // The product C = F·B, then the refit with fewer control points (or, failing that, C's knots
    // removed).
    ASSERT_EQ(c.steps.size(), 2u);
    EXPECT_EQ(c.steps[0].name, "product");
    EXPECT_LT(c.steps[1].control_points, c.steps[0].control_points);
    EXPECT_EQ(c.steps[1].control_points, c.curve.size());
    if (c.steps[1].name == "refit") {
      EXPECT_GE(c.curve.degree(), 3);
      EXPECT_LE(c.curve.degree(), 6);
    } else {
      EXPECT_EQ(c.steps[1].name, "knot removal");
      EXPECT_EQ(c.curve.degree(), c.function.degree() + 4);
    }
    EXPECT_LE(c.function_error + c.synchronization_error, 1.01 * tol + c.function_error);
  }
}

INSTANTIATE_TEST_SUITE_P(Cams, ExampleConversion,
                         testing::Values("roller", "flat_faced", "offset_roller", "polynomial"));

TEST(PolarConversion, RqbBaseMeetsToleranceWithMoreArcs) {
  const PolarFunction R = example_contour("roller");
  ConversionOptions quartic, rqb;
  quartic.tolerance = rqb.tolerance = 1e-4;
  quartic.compaction = rqb.compaction = Compaction::none;  // the product C = F·B
  rqb.base = ArcKind::rqb;
  const PolarConversion q = convert_polar_function(R, quartic);
  const PolarConversion r = convert_polar_function(R, rqb);
  EXPECT_LE(dense_radial_error(r.curve, R, 60000), 1e-4);
  EXPECT_EQ(r.curve.degree(), r.function.degree() + 2);
  EXPECT_GT(r.arcs.size(), 2 * q.arcs.size());
}

TEST(PolarConversion, ConstantRadiusIsAnExactCircle) {
  PolarFunction R;
  R.start = 0;
  R.end = 2 * kPi;
  R.derivatives = [](double, int d, double* out) {
    out[0] = 42.5;
    for (int k = 1; k <= d; ++k) out[k] = 0.0;
  };
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    ConversionOptions options;
    options.tolerance = 1e-9;
    options.base = kind;
    const PolarConversion c = convert_polar_function(R, options);
    EXPECT_EQ(c.curve.degree(), kind == ArcKind::rqb ? 2 : 4);
    EXPECT_EQ(c.max_radial_error, c.max_radial_error);  // finite
    for (int k = 0; k <= 10000; ++k) {
      const double u = c.curve.front() + (c.curve.back() - c.curve.front()) * k / 10000;
      EXPECT_NEAR(c.curve(u).norm(), 42.5, 42.5 * 1e-14);
    }
  }
}

TEST(PolarConversion, CurveIsTheProductOfFAndTheBaseCircle) {
  const PolarFunction R = example_contour("offset_roller");
  ConversionOptions options;
  options.tolerance = 1e-5;
  options.compaction = Compaction::none;  // the product step alone (knot removal changes C)
  const PolarConversion c = convert_polar_function(R, options);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> t(c.curve.front(), c.curve.back());
  for (int k = 0; k < 10000; ++k) {
    const double u = t(rng);
    const Eigen::Vector2d expected = c.function(u) * c.base.curve()(u);
    EXPECT_LE((c.curve(u) - expected).norm(), 1e-12 * expected.norm());
  }
  // Arc junctions sit on every breakpoint of R.
  for (double b : R.breakpoints)
    EXPECT_NE(std::find(c.base.breakpoints().begin(), c.base.breakpoints().end(), b),
              c.base.breakpoints().end());
}

// Radial knife-edge with polynomial laws: R is a piecewise polynomial, represented exactly, so
// the whole error is the base circle's synchronization.
TEST(PolarConversion, PolynomialLawsAreRepresentedExactly) {
  CamDesign cam = test::example_cam_design("polynomial");
  cam.follower = {FollowerKind::KnifeEdge, 0.0, 0.0};
  const PolarFunction R = cam_polar_function(make_plate_cam(cam));
  ASSERT_TRUE(R.exact);
  ConversionOptions options;
  options.tolerance = 1e-6;
  const PolarConversion c = convert_polar_function(R, options);
  EXPECT_TRUE(c.function_exact);
  EXPECT_EQ(c.function_error, 0.0);
  for (int k = 0; k <= 5000; ++k) {
    const double t = R.start + (R.end - R.start) * k / 5000;
    EXPECT_NEAR(c.function(t), R(t), 1e-12 * R(t));
  }
  EXPECT_LE(dense_radial_error(c.curve, R, 60000), 1e-6);
}

TEST(PolarConversion, TighterToleranceNeverNeedsFewerArcs) {
  const PolarFunction R = example_contour("roller");
  std::size_t previous = 0;
  for (double tol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    ConversionOptions options;
    options.tolerance = tol;
    const PolarConversion c = convert_polar_function(R, options);
    EXPECT_GE(c.arcs.size(), previous);
    previous = c.arcs.size();
  }
}

}  // namespace
}  // namespace polarform

namespace polarform {
namespace {

TEST(PolarConversion, AMirrorSymmetricProfileIsRefittedAsItsOwnMirrorImage) {
  const PolarFunction R = test::mirror_symmetric_profile();
  for (double tol : {1e-2, 1e-4}) {
    SCOPED_TRACE(tol);
    ConversionOptions options;
    options.tolerance = tol;
    const PolarConversion c = convert_polar_function(R, options);
    ASSERT_EQ(c.steps.back().name, "refit");
    const NurbsCurve2d& C = c.curve;
    test::expect_own_mirror_image(C);
    const double a = C.front(), b = C.back();
    // Within tol by dense sampling against R.
    double worst = 0.0;
    for (int k = 0; k <= 20000; ++k) {
      const Eigen::Vector2d p = C(a + (b - a) * k / 20000);
      worst = std::max(worst, std::abs(p.norm() - R(std::atan2(p.y(), p.x()))));
    }
    EXPECT_LE(worst, tol);
    EXPECT_LE(c.max_radial_error, tol);
  }
}

}  // namespace
}  // namespace polarform

namespace polarform {
namespace {

// A tolerance below what R's evaluation can reach: the product's arc splitting gives up with a
// NumericalError, and the refit running beside it is stopped (the conversion returns rather than
// waiting for a refit to 1e-12 mm).
TEST(PolarConversion, AnUnreachableToleranceFailsAndStopsTheRefit) {
  ConversionOptions options;
  options.tolerance = 1e-12;
  EXPECT_THROW(convert_polar_function(example_contour("roller"), options), NumericalError);
}

}  // namespace
}  // namespace polarform
