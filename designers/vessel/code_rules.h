// ASME BPVC Section VIII Division 1 rules for internal pressure on inside dimensions: the required
// thickness and the maximum allowable working pressure (MAWP) of a cylindrical shell (UG-27(c)(1)
// and (2)), a hemispherical head (UG-32(f)), an ellipsoidal head (2:1: UG-32(d), other ratios:
// Mandatory Appendix 1-4(c)) and a torispherical head (100 %/6 %: UG-32(e), other proportions:
// Appendix 1-4(d)) and a conical head (UG-32(g); with a knuckle, UG-32(h): the cone on the
// diameter Di where it meets the knuckle, the knuckle by Appendix 1-4(d) with L = Di/(2 cos α)),
// with a corrosion allowance, and the limits of applicability they state.
//
// Paragraph letters as in the editions that letter the head rules (d), (e), (f), e.g. the 1983
// edition; later editions letter them (c), (d), (e) with unchanged formulas. Not implemented: the
// outside-dimension formulas (Appendix 1-1, 1-4 on outside dimensions), thick-wall rules beyond the
// limits (only warned of), Appendix 1-4(f) (only flagged), external pressure, UG-16's minimum.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace polarform {

// All dimensions are inside dimensions in mm, uncorroded (as ordered).
struct CylindricalShell {
  double inside_radius = 0.0;  // R
  // E of the circumferential joints, which carry the longitudinal stress (UG-27(c)(2)); the
  // design's joint efficiency when empty.
  std::optional<double> circumferential_joint_efficiency;
};

struct HemisphericalHead {
  double inside_radius = 0.0;  // L
};

struct EllipsoidalHead {
  double inside_diameter = 0.0;  // D
  double inside_depth = 0.0;     // h, without the skirt; D/2h = 2 is the 2:1 head
};

struct TorisphericalHead {
  double inside_diameter = 0.0;  // D of the skirt
  double crown_radius = 0.0;     // L, >= D/2
  double knuckle_radius = 0.0;   // r, 0 < r < D/2; r = 0.06 L is the 100 %/6 % head
};

struct ConicalHead {
  double inside_diameter = 0.0;  // D of the skirt
  double half_angle = 0.0;       // α, rad, 0 < α < 90°
  double knuckle_radius = 0.0;   // r, 0 <= r < D/2; 0 is a cone without knuckle (UG-32(g))
};
using PressurePart = std::variant<CylindricalShell, HemisphericalHead, EllipsoidalHead,
                                  TorisphericalHead, ConicalHead>;

struct InternalPressureDesign {
  double allowable_stress = 0.0;     // S, MPa, > 0
  double joint_efficiency = 1.0;     // E in (0, 1]; the longitudinal joints' for the cylinder
  double pressure = 0.0;             // P, design pressure, MPa, > 0
  double corrosion_allowance = 0.0;  // c, mm, >= 0
  double nominal_thickness = 0.0;    // t, mm, > c: the thickness whose MAWP is wanted
  PressurePart part;
};

struct CodeCheck {
  // P's formula on the corroded dimensions (D + 2c, R + c, L + c, r + c, h + c) plus c, mm;
  // the larger of UG-27(c)(1) and (2) for the cylinder.
  double required_thickness = 0.0;
  std::string thickness_formula;  // the governing one, e.g. "UG-32(d) 2:1 ellipsoidal"
  // The formula solved for P with t − c on the corroded dimensions, MPa; the smaller of the two for
  // the cylinder.
  double mawp = 0.0;
  std::string mawp_formula;
  // One line per limit of applicability exceeded (listed at check_internal_pressure), e.g.
  // "UG-27(c)(1): design pressure P = 60 MPa exceeds 0.385·S·E = 53.13 MPa"; empty when none is.
  std::vector<std::string> warnings;
};

// The 2:1 ellipsoidal head is recognised by D/2h = 2 and the 100 %/6 % head by r = 0.06 L on the
// uncorroded dimensions (to 1e-9 relative); others take Appendix 1-4 with K or M computed on the
// corroded dimensions. Throws InputError naming the field and its range for bad input: S <= 0, E
// outside (0, 1], P <= 0, c < 0, t <= c, a dimension that makes no head, or P beyond the formula
// (P >= S·E/0.6 for UG-27(c)(1), P >= 10·S·E for the heads).
// Warnings: cylinder P > 0.385·S·E (UG-27(c)(1)), P > 1.25·S·E_c (UG-27(c)(2)), t − c > R/2;
// hemisphere P > 0.665·S·E, t − c > 0.356·L (UG-27(d) through UG-32(f)); ellipsoid D/2h outside
// Table 1-4.1's 1 to 3 (Appendix 1-4(c) only); torispherical head L/r > 16⅔ (Appendix 1-4(d)
// only), L > D + 2t, r < 0.06·(D + 2t), r < 3t (UG-32(j)), t − c < 0.002·L (Appendix 1-4(f) then
// applies and is not checked); cone α > 30° (UG-32(g), (h): Appendix 1-5 then applies and is not
// checked), knuckle r < 0.06·(D + 2t) or < 3t (UG-32(h)). t and D, L, r of UG-32(h), (j) are
// nominal; the rest corroded.
CodeCheck check_internal_pressure(const InternalPressureDesign& design);

// K = (2 + (D/2h)²)/6, Appendix 1-4(c); 1 for the 2:1 head. Throws InputError unless D, h > 0.
double ellipsoidal_head_factor(double inside_diameter, double inside_depth);

// M = (3 + √(L/r))/4, Appendix 1-4(d); 1.77 (printed) for L/r = 16⅔. Throws unless L, r > 0.
double torispherical_head_factor(double crown_radius, double knuckle_radius);

}  // namespace polarform
