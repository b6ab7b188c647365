// ASME VIII-1 internal-pressure rules against hand computation written out here (S = 138 MPa,
// E = 1, P = 1.5 MPa, D = 1000 mm unless a test says otherwise; the decimals from a 30-digit
// evaluation), the inverse pair t(P), P(t), the factors K and M against Appendix 1-4's tables, the
// Appendix 1-4 formulas against UG-32(d) and (e), the limits of applicability and the bad inputs.
#include "designers/vessel/code_rules.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

InternalPressureDesign design(PressurePart part, double P = 1.5, double t = 10, double c = 0,
                              double E = 1) {
  return {138, E, P, c, t, part};
}

const CylindricalShell kShell{500, {}};
const HemisphericalHead kHemisphere{500};
const EllipsoidalHead kTwoToOne{1000, 250};
const TorisphericalHead kHundredSix{1000, 1000, 60};

// t = PD/(2SE − 0.2P) = 1.5·1000/(2·138 − 0.3) = 1500/275.7 = 5.440696409…;
// MAWP at t = 10: 2·138·10/(1000 + 2) = 2.754491018.
TEST(CodeRules, TwoToOneEllipsoidalHead) {
  const CodeCheck c = check_internal_pressure(design(kTwoToOne));
  EXPECT_NEAR(c.required_thickness, 1500 / 275.7, 1e-14);
  EXPECT_NEAR(c.required_thickness, 5.440696409140370, 1e-14);
  EXPECT_NEAR(c.mawp, 2760.0 / 1002, 1e-14);
  EXPECT_EQ(c.thickness_formula, "UG-32(d) 2:1 ellipsoidal");
  EXPECT_EQ(c.mawp_formula, "UG-32(d) 2:1 ellipsoidal");
  EXPECT_TRUE(c.warnings.empty());
}

// Corrosion c = 3: D = 1006 in the formula, plus c: 1.5·1006/275.7 + 3 = 8.473340588;
// MAWP of t = 10 on t − c = 7: 2·138·7/(1006 + 1.4) = 1932/1007.4 = 1.917808219.
TEST(CodeRules, CorrosionAllowance) {
  const CodeCheck c = check_internal_pressure(design(kTwoToOne, 1.5, 10, 3));
  EXPECT_NEAR(c.required_thickness, 1509 / 275.7 + 3, 1e-14);
  EXPECT_NEAR(c.required_thickness, 8.473340587595212, 1e-14);
  EXPECT_NEAR(c.mawp, 1932 / 1007.4, 1e-14);
  EXPECT_NEAR(c.mawp, 1.917808219178082, 1e-14);
}

// UG-27(c)(1): t = PR/(SE − 0.6P) = 750/137.1 = 5.470459519 beats (c)(2): 750/276.6 = 2.711496746;
// c = 3, t = 10: 1.5·503/137.1 + 3 = 8.503282276, MAWP 138·7/(503 + 4.2) = 1.904574132.
TEST(CodeRules, CylinderCircumferentialStressGoverns) {
  const CodeCheck c = check_internal_pressure(design(kShell));
  EXPECT_NEAR(c.required_thickness, 750 / 137.1, 1e-14);
  EXPECT_NEAR(c.required_thickness, 5.470459518599562, 1e-14);
  EXPECT_NEAR(c.mawp, 1380.0 / 506, 1e-14);
  EXPECT_EQ(c.thickness_formula, "UG-27(c)(1) cylinder, circumferential stress");
  EXPECT_EQ(c.mawp_formula, "UG-27(c)(1) cylinder, circumferential stress");
  const CodeCheck corroded = check_internal_pressure(design(kShell, 1.5, 10, 3));
  EXPECT_NEAR(corroded.required_thickness, 8.503282275711160, 1e-14);
  EXPECT_NEAR(corroded.mawp, 1.904574132492114, 1e-14);
  EXPECT_TRUE(corroded.warnings.empty());
}

// Circumferential joints of E = 0.35 under longitudinal joints of E = 1: UG-27(c)(2) needs
// 750/(2·138·0.35 + 0.6) = 750/97.2 = 7.716049383 > 5.470459519 and, at t = 100, allows
// 2·138·0.35·100/(500 − 40) = 21 < 138·100/560 = 24.64285714; the two cross at P = S(E − 2E_c) =
// 41.4 MPa, so at t = 200 circumferential stress limits the MAWP: 27600/620 = 44.51612903 < 46.
TEST(CodeRules, CylinderLongitudinalStressWithWeakCircumferentialJoints) {
  const CylindricalShell shell{500, 0.35};
  const CodeCheck c = check_internal_pressure(design(shell, 1.5, 100));
  EXPECT_NEAR(c.required_thickness, 750 / 97.2, 1e-14);
  EXPECT_EQ(c.thickness_formula, "UG-27(c)(2) cylinder, longitudinal stress");
  EXPECT_NEAR(c.mawp, 21.0, 1e-13);
  EXPECT_EQ(c.mawp_formula, "UG-27(c)(2) cylinder, longitudinal stress");
  const CodeCheck thick = check_internal_pressure(design(shell, 1.5, 200));
  EXPECT_EQ(thick.thickness_formula, "UG-27(c)(2) cylinder, longitudinal stress");
  EXPECT_NEAR(thick.mawp, 27600.0 / 620, 1e-13);
  EXPECT_EQ(thick.mawp_formula, "UG-27(c)(1) cylinder, circumferential stress");
}

// UG-27(c)(2)'s t = PR/(2SE + 0.4P) stays below 2.5 R: a wall of 2.6 R is rated by (c)(1) alone,
// 138·260/(100 + 156) = 140.15625, and warned of.
TEST(CodeRules, CylinderBeyondTheLongitudinalFormula) {
  const CodeCheck c = check_internal_pressure(design(CylindricalShell{100, {}}, 1.5, 260));
  EXPECT_NEAR(c.mawp, 140.15625, 1e-12);
  EXPECT_EQ(c.mawp_formula, "UG-27(c)(1) cylinder, circumferential stress");
  EXPECT_THAT(c.warnings,
              ElementsAre("UG-27(c): corroded thickness t − c = 260 mm exceeds R/2 = 50 mm"));
}

// UG-32(f): 750/275.7 = 2.720348205; E = 0.85, c = 2: 1.5·502/(2·117.3 − 0.3) + 2 = 5.213828425,
// MAWP of t − c = 8: 2·117.3·8/(502 + 1.6) = 3.726767276.
TEST(CodeRules, HemisphericalHead) {
  const CodeCheck c = check_internal_pressure(design(kHemisphere));
  EXPECT_NEAR(c.required_thickness, 750 / 275.7, 1e-14);
  EXPECT_EQ(c.thickness_formula, "UG-32(f) hemispherical");
  const CodeCheck e = check_internal_pressure(design(kHemisphere, 1.5, 10, 2, 0.85));
  EXPECT_NEAR(e.required_thickness, 5.213828425096031, 1e-14);
  EXPECT_NEAR(e.mawp, 3.726767275615568, 1e-14);
  EXPECT_TRUE(e.warnings.empty());
}

// UG-32(e): 0.885·1.5·1000/(138 − 0.15) = 1327.5/137.85 = 9.630032644; E = 0.85, c = 2:
// 0.885·1.5·1002/(117.3 − 0.15) + 2 = 13.35428937, MAWP 117.3·8/(0.885·1002 + 0.8) = 1.057268722.
// A crown of the inside diameter is 0.06·1000 = 60 < 0.06·(D + 2t) = 61.2: UG-32(j) is warned of.
TEST(CodeRules, HundredSixTorisphericalHead) {
  const CodeCheck c = check_internal_pressure(design(kHundredSix));
  EXPECT_NEAR(c.required_thickness, 1327.5 / 137.85, 1e-14);
  EXPECT_NEAR(c.required_thickness, 9.630032644178455, 1e-14);
  EXPECT_NEAR(c.mawp, 1380.0 / 886, 1e-14);
  EXPECT_EQ(c.thickness_formula, "UG-32(e) 100 %/6 % torispherical");
  EXPECT_THAT(c.warnings,
              ElementsAre("UG-32(j): 0.06·(D + 2t) = 61.2 mm exceeds knuckle radius r = 60 mm"));
  const CodeCheck e = check_internal_pressure(design(kHundredSix, 1.5, 10, 2, 0.85));
  EXPECT_NEAR(e.required_thickness, 13.35428937259923, 1e-13);
  EXPECT_NEAR(e.mawp, 1.057268722466960, 1e-14);
  // The standard head on its outside diameter (L = D + 2t, r = 0.06 L) meets UG-32(j).
  const TorisphericalHead standard{1000, 1020, 61.2};
  EXPECT_TRUE(check_internal_pressure(design(standard)).warnings.empty());
}

// D/2h = 2.5: K = (2 + 6.25)/6 = 1.375, t = 1.5·1000·1.375/275.7 = 7.480957563; E = 0.85, c = 2:
// K = (2 + (1004/404)²)/6 = 1.362660523, t = 1.5·1004·K/234.3 + 2 = 10.75871425,
// MAWP 2·117.3·8/(1004·K + 1.6) = 1.370215887.
TEST(CodeRules, AppendixEllipsoidalHead) {
  const CodeCheck c = check_internal_pressure(design(EllipsoidalHead{1000, 200}));
  EXPECT_NEAR(c.required_thickness, 1500 * 1.375 / 275.7, 1e-14);
  EXPECT_NEAR(c.required_thickness, 7.480957562568009, 1e-14);
  EXPECT_EQ(c.thickness_formula, "Appendix 1-4(c) ellipsoidal, K = 1.375");
  EXPECT_TRUE(c.warnings.empty());
  const CodeCheck e = check_internal_pressure(design(EllipsoidalHead{1000, 200}, 1.5, 10, 2, 0.85));
  EXPECT_NEAR(e.required_thickness, 10.75871424822025, 1e-13);
  EXPECT_NEAR(e.mawp, 1.370215887242354, 1e-14);
  EXPECT_EQ(e.mawp_formula, "Appendix 1-4(c) ellipsoidal, K = 1.36266");
}

// 80 %/10 %: L/r = 8, M = (3 + √8)/4 = 1.457106781, t = 1.5·800·M/275.7 = 6.342140506; E = 0.85,
// c = 2: M = (3 + √(802/102))/4 = 1.451014671, t = 9.450152151, MAWP 2·117.3·8/(802·M + 1.6) =
// 1.610553359.
TEST(CodeRules, AppendixTorisphericalHead) {
  const CodeCheck c = check_internal_pressure(design(TorisphericalHead{1000, 800, 100}));
  EXPECT_NEAR(c.required_thickness, 6.342140505708586, 1e-14);
  EXPECT_EQ(c.thickness_formula, "Appendix 1-4(d) torispherical, M = 1.45711");
  EXPECT_TRUE(c.warnings.empty());
  const CodeCheck e =
      check_internal_pressure(design(TorisphericalHead{1000, 800, 100}, 1.5, 10, 2, 0.85));
  EXPECT_NEAR(e.required_thickness, 9.450152150789708, 1e-13);
  EXPECT_NEAR(e.mawp, 1.610553358961288, 1e-14);
}

// Tables 1-4.1 and 1-4.2 print K = 1.00 at D/2h = 2, 1.83 at 3 and 0.50 at 1; M = 1.00 at L/r = 1
// and 1.77 at 16⅔ (UG-32(e)'s 0.885 = 1.77/2).
TEST(CodeRules, ShapeFactors) {
  EXPECT_EQ(ellipsoidal_head_factor(1000, 250), 1.0);
  EXPECT_NEAR(ellipsoidal_head_factor(1200, 200), 11.0 / 6, 1e-15);
  EXPECT_EQ(ellipsoidal_head_factor(1000, 500), 0.5);
  EXPECT_EQ(torispherical_head_factor(100, 100), 1.0);
  const double m = torispherical_head_factor(1000, 60);
  EXPECT_NEAR(m, 1.770620726159658, 1e-15);
  EXPECT_EQ(std::round(m * 100) / 100, 1.77);
}

// Just off the 2:1 and 100 %/6 % proportions the Appendix 1-4 formulas take over, and their
// thickness is UG-32's times K and M/1.77 exactly (t = 0.885PL/(SE − 0.1P) = 1.77PL/(2SE − 0.2P)).
TEST(CodeRules, AppendixFormulasReduceToUg32) {
  const double h = 250 * (1 + 1e-6);
  const CodeCheck near_two = check_internal_pressure(design(EllipsoidalHead{1000, h}));
  EXPECT_THAT(near_two.thickness_formula, HasSubstr("Appendix 1-4(c)"));
  const CodeCheck two = check_internal_pressure(design(kTwoToOne));
  EXPECT_NEAR(near_two.required_thickness / two.required_thickness,
              ellipsoidal_head_factor(1000, h), 1e-14);
  EXPECT_NEAR(near_two.required_thickness, two.required_thickness, 1e-5);

  const double r = 60 * (1 + 1e-6);
  const CodeCheck near_six = check_internal_pressure(design(TorisphericalHead{1000, 1000, r}));
  EXPECT_THAT(near_six.thickness_formula, HasSubstr("Appendix 1-4(d)"));
  const CodeCheck six = check_internal_pressure(design(kHundredSix));
  EXPECT_NEAR(near_six.required_thickness / six.required_thickness,
              torispherical_head_factor(1000, r) / 1.77, 1e-14);
  // M = 1.7706 against the rounded 1.77: the Appendix asks 3.5e-4 more.
  EXPECT_NEAR(near_six.required_thickness / six.required_thickness - 1, 3.507e-4, 1e-6);
}

// Required thickness as the nominal one gives back the design pressure as MAWP, for every part,
// pressures from 0.1 to 50 MPa and corrosion allowances 0 and 3 mm.
// UG-32(g), α = 30°, D = 1000: t = PD/(2 cos α (SE − 0.6P)) = 1500/(√3·(138 − 0.9)) =
// 6.316742551…; MAWP at t = 10: 2·138·10·cos α/(1000 + 12 cos α) = 2.365645604… MPa.
// UG-32(h) with r = 60: the cone on Di = 1000 − 120(1 − cos α) = 983.9230485, t = 6.215188587…;
// the knuckle by Appendix 1-4(d), L = Di/(2 cos α) = 568.0682…, M = (3 + √(L/r))/4 = 1.519245…,
// t = PLM/(2SE − 0.2P) = 4.6955…, so the cone governs.
TEST(CodeRules, ConicalHeads) {
  const double a = std::acos(-1.0) / 6, ca = std::cos(a);
  const CodeCheck cone = check_internal_pressure(design(ConicalHead{1000, a, 0}));
  EXPECT_NEAR(cone.required_thickness, 1.5 * 1000 / (2 * ca * (138 - 0.9)), 1e-12);
  EXPECT_NEAR(cone.required_thickness, 6.316742551, 1e-9);
  EXPECT_NEAR(cone.mawp, 2 * 138 * 10 * ca / (1000 + 12 * ca), 1e-12);
  EXPECT_NEAR(cone.mawp, 2.365645604, 1e-9);
  EXPECT_EQ(cone.thickness_formula, "UG-32(g) conical");
  const CodeCheck tori = check_internal_pressure(design(ConicalHead{1000, a, 60}));
  const double Di = 1000 - 120 * (1 - ca), L = Di / (2 * ca), M = (3 + std::sqrt(L / 60)) / 4;
  EXPECT_NEAR(tori.required_thickness, 1.5 * Di / (2 * ca * (138 - 0.9)), 1e-12);
  EXPECT_NEAR(tori.required_thickness, 6.215188587, 1e-9);
  EXPECT_EQ(tori.thickness_formula, "UG-32(h) toriconical, cone");
  EXPECT_GT(1.5 * Di / (2 * ca * (138 - 0.9)), 1.5 * L * M / (276 - 0.3));
  // A sharp knuckle governs: r = 5 mm.
  const CodeCheck sharp = check_internal_pressure(design(ConicalHead{1000, a, 5}));
  EXPECT_THAT(sharp.thickness_formula, HasSubstr("knuckle, Appendix 1-4(d)"));
  EXPECT_THAT(sharp.warnings, testing::Contains(HasSubstr("UG-32(h): 0.06·(D + 2t)")));
  const CodeCheck steep = check_internal_pressure(design(ConicalHead{1000, a * 1.5, 0}));
  EXPECT_THAT(steep.warnings, testing::Contains(HasSubstr("UG-32(g): half apex angle α = 45")));
  EXPECT_THROW(check_internal_pressure(design(ConicalHead{1000, 0.0, 0})), InputError);
  EXPECT_THROW(check_internal_pressure(design(ConicalHead{1000, a, 500})), InputError);
}

TEST(CodeRules, ThicknessAndPressureInvertEachOther) {
  const PressurePart parts[] = {kShell,
                                CylindricalShell{500, 0.35},
                                kHemisphere,
                                kTwoToOne,
                                EllipsoidalHead{1000, 180},
                                EllipsoidalHead{1000, 600},
                                kHundredSix,
                                TorisphericalHead{1000, 800, 100},
                                TorisphericalHead{1000, 3000, 40},
                                ConicalHead{1000, 0.5, 0},
                                ConicalHead{1000, 0.5, 80},
                                ConicalHead{1000, 1.2, 10}};
  for (const PressurePart& part : parts)
    for (const double P : {0.1, 1.5, 10.0, 50.0})
      for (const double c : {0.0, 3.0}) {
        const double t = check_internal_pressure(design(part, P, c + 1, c)).required_thickness;
        const CodeCheck check = check_internal_pressure(design(part, P, t, c));
        EXPECT_NEAR(check.required_thickness, t, 1e-12 * t);
        EXPECT_NEAR(check.mawp, P, 1e-12 * P)
            << check.thickness_formula << " P = " << P << " c = " << c;
        EXPECT_EQ(check.mawp_formula, check.thickness_formula);
      }
}

TEST(CodeRules, LimitsOfApplicabilityAreWarned) {
  // 0.385·138 = 53.13 MPa; the wall this needs, 60·500/102 = 294 mm, is past R/2.
  EXPECT_THAT(check_internal_pressure(design(kShell, 60, 300)).warnings,
              ElementsAre("UG-27(c)(1): design pressure P = 60 MPa exceeds 0.385·S·E = 53.13 MPa",
                          "UG-27(c): corroded thickness t − c = 300 mm exceeds R/2 = 250 mm"));
  EXPECT_THAT(check_internal_pressure(design(CylindricalShell{500, 0.3}, 60)).warnings,
              ElementsAre("UG-27(c)(1): design pressure P = 60 MPa exceeds 0.385·S·E = 53.13 MPa",
                          "UG-27(c)(2): design pressure P = 60 MPa exceeds 1.25·S·E = 51.75 MPa"));
  EXPECT_THAT(check_internal_pressure(design(kHemisphere, 100, 200)).warnings,
              ElementsAre("UG-32(f): design pressure P = 100 MPa exceeds 0.665·S·E = 91.77 MPa",
                          "UG-32(f): corroded thickness t − c = 200 mm exceeds 0.356·L = 178 mm"));
  EXPECT_THAT(check_internal_pressure(design(EllipsoidalHead{1000, 140})).warnings,
              ElementsAre("Appendix 1-4(c): D/2h = 3.57143 lies outside Table 1-4.1 (1 to 3)"));
  EXPECT_THAT(check_internal_pressure(design(EllipsoidalHead{1000, 600})).warnings,
              ElementsAre("Appendix 1-4(c): D/2h = 0.833333 lies outside Table 1-4.1 (1 to 3)"));
  EXPECT_THAT(
      check_internal_pressure(design(TorisphericalHead{1000, 1100, 50}, 0.1, 20)).warnings,
      ElementsAre("UG-32(j): crown radius L = 1100 mm exceeds outside diameter D + 2t = 1040 mm",
                  "UG-32(j): 0.06·(D + 2t) = 62.4 mm exceeds knuckle radius r = 50 mm",
                  "UG-32(j): 3t = 60 mm exceeds knuckle radius r = 50 mm",
                  "Appendix 1-4(d): L/r = 22 exceeds 16 2/3 (Table 1-4.2) = 16.6667"));
  EXPECT_THAT(check_internal_pressure(design(TorisphericalHead{1000, 1000, 80}, 0.1, 1.5)).warnings,
              ElementsAre("Appendix 1-4(f) applies (not checked): 0.002·L = 2 mm exceeds corroded "
                          "thickness t − c = 1.5 mm"));
}

TEST(CodeRules, BadInputNamesTheFieldAndItsRange) {
  const auto message = [](const InternalPressureDesign& d) {
    try {
      check_internal_pressure(d);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  InternalPressureDesign d = design(kTwoToOne);
  d.allowable_stress = 0;
  EXPECT_EQ(message(d), "code rules: allowable stress S = 0 MPa, expected > 0");
  d = design(kTwoToOne, 1.5, 10, 0, 1.2);
  EXPECT_EQ(message(d), "code rules: joint efficiency E = 1.2, expected in (0, 1]");
  d = design(kTwoToOne, 1.5, 10, 0, 0);
  EXPECT_EQ(message(d), "code rules: joint efficiency E = 0, expected in (0, 1]");
  EXPECT_EQ(message(design(kTwoToOne, 0)), "code rules: design pressure P = 0 MPa, expected > 0");
  EXPECT_EQ(message(design(kTwoToOne, 1.5, 10, -1)),
            "code rules: corrosion allowance c = -1 mm, expected >= 0");
  EXPECT_EQ(message(design(kTwoToOne, 1.5, 3, 3)),
            "code rules: nominal thickness t = 3 mm, expected > corrosion allowance c = 3 mm");
  EXPECT_EQ(message(design(CylindricalShell{0, {}})),
            "code rules: cylindrical shell: inside radius R = 0 mm, expected > 0");
  EXPECT_EQ(message(design(CylindricalShell{500, 1.5})),
            "code rules: cylindrical shell: circumferential joint efficiency = 1.5, expected in "
            "(0, 1]");
  EXPECT_EQ(message(design(kShell, 231)),
            "code rules: design pressure P = 231 MPa, expected < S·E/0.6 = 230 MPa for "
            "UG-27(c)(1)");
  EXPECT_EQ(message(design(kHemisphere, 1380)),
            "code rules: design pressure P = 1380 MPa, expected < 10·S·E = 1380 MPa for UG-32(f) "
            "hemispherical");
  EXPECT_EQ(message(design(HemisphericalHead{-5})),
            "code rules: hemispherical head: inside radius L = -5 mm, expected > 0");
  EXPECT_EQ(message(design(EllipsoidalHead{1000, 0})),
            "code rules: ellipsoidal head: inside depth h = 0 mm, expected > 0");
  EXPECT_EQ(message(design(EllipsoidalHead{NAN, 250})),
            "code rules: ellipsoidal head: inside diameter D = nan mm, expected > 0");
  EXPECT_EQ(message(design(TorisphericalHead{1000, 1000, 500})),
            "code rules: torispherical head: knuckle radius r = 500 mm, expected 0 < r < D/2 = "
            "500 mm");
  EXPECT_EQ(message(design(TorisphericalHead{1000, 400, 60})),
            "code rules: torispherical head: crown radius L = 400 mm, expected >= D/2 = 500 mm");
  EXPECT_THROW(ellipsoidal_head_factor(0, 250), InputError);
  EXPECT_THROW(torispherical_head_factor(1000, -1), InputError);
}

}  // namespace
}  // namespace polarform
