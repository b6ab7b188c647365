// A vessel against ASME VIII-1 and its measures: the shell's and the exact head's formulas at the
// design's pressure and wall, the smaller MAWP, and volumes and weight from the closed forms,
// checked here by hand arithmetic.
#include "designers/vessel/vessel_code_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// 2:1 head on R = 500 mm, t = 10 mm, P = 2 MPa, S = 138 MPa, E = 1: shell t = PR/(SE − 0.6P),
// head t = PD/(2SE − 0.2P); MAWP = min(SEt/(R + 0.6t), 2SEt/(D + 0.2t)).
TEST(VesselCodeCheck, ShellAndExactHeadByTheirFormulas) {
  const VesselCodeCheck c =
      check_vessel_code({138, 1, 0}, 500, 10, 2, HeadPreset{HeadKind::ellipsoidal, 2.0});
  EXPECT_NEAR(c.shell.required_thickness, 1000 / 136.8, 1e-12);
  ASSERT_TRUE(c.head);
  EXPECT_NEAR(c.head->required_thickness, 2000 / 275.6, 1e-12);
  EXPECT_NEAR(c.mawp, std::min(1380 / 506.0, 2760 / 1002.0), 1e-12);
  EXPECT_TRUE(c.thickness_sufficient);
  // 6 mm is too thin for both; with 2 mm corrosion allowance the shell needs 2 + 1002/136.8.
  EXPECT_FALSE(check_vessel_code({138, 1, 0}, 500, 6, 2, std::nullopt).thickness_sufficient);
  const VesselCodeCheck corroded = check_vessel_code({138, 1, 2}, 500, 10, 2, std::nullopt);
  EXPECT_NEAR(corroded.shell.required_thickness, 2 + 2 * 502 / 136.8, 1e-12);
  EXPECT_FALSE(corroded.head);
  EXPECT_NE(corroded.head_note.find("not a code head"), std::string::npos);
}

TEST(VesselCodeCheck, MeasuresOfAVesselWithTwoHeads) {
  const double R = 500, L = 1500, t = 10;
  const VesselMeasures m = vessel_measures(HeadPreset{HeadKind::hemispherical}, R, L, t, 7850);
  const double inside = 4.0 / 3 * kPi * R * R * R + kPi * R * R * L;
  const double outside = 4.0 / 3 * kPi * std::pow(R + t, 3) + kPi * (R + t) * (R + t) * L;
  EXPECT_NEAR(m.vessel_volume, inside, 1e-9 * inside);
  EXPECT_NEAR(m.metal_volume, outside - inside, 1e-9 * (outside - inside));
  EXPECT_NEAR(m.weight, (outside - inside) * 1e-9 * 7850, 1e-9 * m.weight);
  EXPECT_NEAR(m.head_area, 2 * kPi * R * R, 1e-9 * m.head_area);
}

TEST(VesselCodeCheck, BadInputsNameTheField) {
  EXPECT_THROW(check_vessel_code({0, 1, 0}, 500, 10, 2, std::nullopt), InputError);
  EXPECT_THROW(check_vessel_code({138, 1.5, 0}, 500, 10, 2, std::nullopt), InputError);
  EXPECT_THROW(check_vessel_code({138, 1, 12}, 500, 10, 2, std::nullopt), InputError);  // t <= c
}

}  // namespace
}  // namespace polarform
