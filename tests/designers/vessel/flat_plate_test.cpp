// The flanged flat head's plate (flat_plate.h): Timoshenko's circular-plate stresses at hand-worked
// values, and the vessel design that reports them — membrane stresses at the junction only, no
// UG-32 head check, the plate radius R − r.
#include "designers/vessel/flat_plate.h"

#include <gtest/gtest.h>

#include "designers/vessel/vessel_design.h"
#include "src/error.h"

namespace polarform {
namespace {

// a = 440 mm, t = 40 mm, p = 0.5 MPa, ν = 0.3: p a²/t² = 60.5, so clamped edge 3/4 · 60.5 =
// 45.375, clamped centre 3·1.3/8 · 60.5 = 29.49375, simply supported centre 3·3.3/8 · 60.5 =
// 74.86875 MPa.
TEST(FlatPlate, TimoshenkoPlateStresses) {
  const FlatPlateBending b = flat_plate_bending(440, 40, 0.5, 0.3);
  EXPECT_NEAR(b.clamped_edge, 45.375, 1e-12);
  EXPECT_NEAR(b.clamped_centre, 29.49375, 1e-12);
  EXPECT_NEAR(b.simply_supported_centre, 74.86875, 1e-12);
  EXPECT_THROW(flat_plate_bending(440, 0, 0.5, 0.3), InputError);
  EXPECT_THROW(flat_plate_bending(440, 40, 0.5, 0.5), InputError);
}

TEST(FlatPlate, FlatHeadDesign) {
  VesselDesign d;
  d.radius = 500, d.length = 1500, d.thickness = 40, d.pressure = 0.5;
  d.preset = HeadPreset{HeadKind::flat, 2.0, 0.0, 60};
  d.head_design = HeadDesign::exact;
  d.code = CodeInputs{138, 1.0, 0.0};
  const VesselSolution s = solve_vessel(d);
  ASSERT_TRUE(s.flat_plate);
  EXPECT_NEAR(s.flat_plate->plate_radius, 440, 1e-9);
  EXPECT_NEAR(s.flat_plate->clamped_edge, 45.375, 1e-9);
  EXPECT_NEAR(s.depth, 60, 1e-9);
  // Membrane stresses: the cylinder's two samples and the junction on the knuckle side, where
  // N_θ = p R (1 − R/(2r)) = 0.5·500·(1 − 500/120) → σθ = −19.79 MPa.
  ASSERT_EQ(s.stresses.samples.size(), 3u);
  EXPECT_NEAR(s.stresses.samples.back().hoop_stress, 0.5 * 500 * (1 - 500 / 120.0) / 40, 1e-9);
  ASSERT_EQ(s.edge_bending.size(), 1u);  // the junction only, not the knuckle–plate joint
  EXPECT_EQ(s.edge_bending[0].theta, 0.0);
  ASSERT_TRUE(s.code);
  EXPECT_FALSE(s.code->head);
  EXPECT_NE(s.code->head_note.find("UG-34"), std::string::npos);
  ASSERT_TRUE(s.measures);
  EXPECT_NEAR(s.measures->head_volume, head_measures(*d.preset, 500).volume, 1e-6);
}

}  // namespace
}  // namespace polarform
