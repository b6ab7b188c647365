// Knot removal on the converted product within the tolerance (issue 14): on every plate-cam
// example at 1e-2, 1e-3 and 1e-4 mm the compacted profile has fewer control points than the
// product, its error measured by the tests' own dense sampling stays within the tolerance, the
// steps are recorded, and with full compaction at the examples' 1e-3 mm no interior knot is C0
// (readers see one smooth curve); by default R's breakpoints keep their exact arc junctions.
#include <gtest/gtest.h>

#include "designers/cam/contour_polar_function.h"
#include "designers/convert/polar_conversion.h"
#include "tests/support/designers/contour_distance.h"
#include "tests/support/designers/example_cams.h"

namespace polarform {
namespace {

const std::vector<std::string> kPlateCams = {"roller", "flat_faced", "offset_roller", "polynomial"};

PolarFunction contour(const std::string& name) {
  return cam_polar_function(make_plate_cam(test::example_cam_design(name)));
}

TEST(MeasuredKnotRemoval, FewerControlPointsWithinTheToleranceByDenseSampling) {
  for (const std::string& name : kPlateCams)
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      SCOPED_TRACE(name + " at " + std::to_string(tol));
      const PolarFunction R = contour(name);
      ConversionOptions options;
      options.tolerance = tol;
      options.compaction = Compaction::full;
      const PolarConversion c = convert_polar_function(R, options);
      ASSERT_EQ(c.steps.size(), 2u);
      EXPECT_EQ(c.steps[0].name, "product");
      EXPECT_EQ(c.steps[1].name, "knot removal");
      EXPECT_EQ(c.steps[1].control_points, c.curve.size());
      EXPECT_LT(c.steps[1].control_points, 0.8 * c.steps[0].control_points);
      EXPECT_LE(c.max_radial_error, tol);
      const double dense = test::max_contour_distance([&](double u) { return c.curve(u); },
                                                      c.curve.front(), c.curve.back(), R, 40000);
      EXPECT_LE(dense, tol);
    }
}

TEST(MeasuredKnotRemoval, FullCompactionLeavesNoC0KnotAtTheExamplesTolerance) {
  for (const std::string& name : kPlateCams) {
    SCOPED_TRACE(name);
    ConversionOptions options;
    options.tolerance = 1e-3;
    options.compaction = Compaction::full;
    const PolarConversion c = convert_polar_function(contour(name), options);
    for (const Breakpoint& k : breakpoints(c.curve.knots())) {
      if (k.value > c.curve.front() && k.value < c.curve.back()) {
        EXPECT_LT(k.multiplicity, c.curve.degree()) << "at " << k.value;
      }
    }
  }
}

TEST(MeasuredKnotRemoval, BetweenBreakpointsKeepsTheArcJunctionsAtBreakpoints) {
  const PolarFunction R = contour("roller");
  ConversionOptions options;
  options.tolerance = 1e-3;
  options.compaction = Compaction::between_breakpoints;
  const PolarConversion c = convert_polar_function(R, options);
  ASSERT_FALSE(R.breakpoints.empty());
  for (double b : R.breakpoints) {
    EXPECT_EQ(multiplicity(c.curve.knots(), b), c.curve.degree()) << "at " << b;
    EXPECT_NEAR((c.curve(b) - R(b) * Eigen::Vector2d(std::cos(b), std::sin(b))).norm(), 0.0,
                c.function_error + 1e-9);
  }
  EXPECT_LT(c.steps[1].control_points, c.steps[0].control_points);
}

}  // namespace
}  // namespace polarform
