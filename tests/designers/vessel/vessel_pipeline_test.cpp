// The whole vessel chain with the real converter: solve → convert to the tolerance → revolve. The
// revolved head must stay within the tolerance of the solved R(θ) everywhere on the surface, and
// the converter must see the apex as an arc junction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/convert/polar_conversion.h"
#include "designers/vessel/vessel_design.h"
#include "designers/vessel/vessel_surfaces.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

VesselDesign custom_design() {
  VesselDesign d;
  d.radius = 500;
  d.length = 1500;
  d.thickness = 10;
  d.pressure = 2;
  const double deg = kPi / 180;
  d.targets = {{10 * deg, 0.0032, 1}, {25 * deg, 0.0028, 1}, {45 * deg, 1 / 450.0, 1},
               {70 * deg, 1 / 550.0, 2}, {90 * deg, 1 / 600.0, 2}, {110 * deg, 1 / 550.0, 2},
               {135 * deg, 1 / 450.0, 1}, {155 * deg, 0.0028, 1}, {170 * deg, 0.0032, 1}};
  d.synthesis.smoothing = 1e-4;
  return d;
}

TEST(VesselPipeline, RevolvedHeadStaysWithinTheConversionTolerance) {
  const VesselSolution s = solve_vessel(custom_design());
  ConversionOptions options;
  options.tolerance = 1e-3;
  options.compaction = Compaction::between_breakpoints;  // as the vessel job converts
  const PolarConversion c = convert_polar_function(s.profile, options);
  EXPECT_LE(c.max_radial_error, 1e-3);
  EXPECT_TRUE(c.function_exact);
  const VesselSurfaces v = vessel_surfaces(c.curve, 1500);
  EXPECT_NEAR(v.apex_parameter, kPi / 2, 1e-12);
  EXPECT_NEAR(v.junction_radius, 500.0, 1e-9);
  // Every surface point: its meridian position (ρ, z) against R at its own polar angle.
  double worst = 0.0;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 90; ++j) {
      const Eigen::Vector3d p = v.head(i / 24.0, v.head.front_v() + (v.head.back_v() - v.head.front_v()) * j / 90);
      const double rho = std::hypot(p.x(), p.y()), psi = std::atan2(p.z(), rho);
      worst = std::max(worst, std::abs(std::hypot(rho, p.z()) - s.profile(psi)));
    }
  EXPECT_LE(worst, 1e-3);
  EXPECT_NEAR(v.head(0.3, v.head.back_v()).z(), s.depth, 1e-3);
}

}  // namespace
}  // namespace polarform
