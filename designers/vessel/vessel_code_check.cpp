#include "designers/vessel/vessel_code_check.h"

#include <algorithm>

#include "designers/vessel/head_measures.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

// The standard head as the code knows it, on inside dimensions.
PressurePart code_part(const HeadPreset& h, double radius) {
  switch (h.kind) {
    case HeadKind::hemispherical:
      return HemisphericalHead{radius};
    case HeadKind::ellipsoidal:
      return EllipsoidalHead{2 * radius, radius / h.ratio};
    case HeadKind::torispherical:
      return TorisphericalHead{2 * radius, h.crown, h.knuckle};
    case HeadKind::conical:
      return ConicalHead{2 * radius, h.half_angle, h.knuckle};
    case HeadKind::flat:
      break;  // not a UG-32 head (check_vessel_code)
  }
  return HemisphericalHead{radius};
}

}  // namespace

VesselCodeCheck check_vessel_code(const CodeInputs& code, double radius, double thickness,
                                  double pressure, const std::optional<HeadPreset>& exact_head) {
  InternalPressureDesign d;
  d.allowable_stress = code.allowable_stress;
  d.joint_efficiency = code.joint_efficiency;
  d.pressure = pressure;
  d.corrosion_allowance = code.corrosion_allowance;
  d.nominal_thickness = thickness;
  d.part = CylindricalShell{radius, std::nullopt};
  VesselCodeCheck out;
  out.shell = check_internal_pressure(d);
  out.mawp = out.shell.mawp;
  double required = out.shell.required_thickness;
  if (exact_head && exact_head->kind == HeadKind::flat) {
    out.head_note =
        "a flat head is not a UG-32 head: its thickness is ruled by UG-34 (factor C and diameter d "
        "by the attachment sketch), which is not computed here";
  } else if (exact_head) {
    d.part = code_part(*exact_head, radius);
    out.head = check_internal_pressure(d);
    out.mawp = std::min(out.mawp, out.head->mawp);
    required = std::max(required, out.head->required_thickness);
  } else {
    out.head_note =
        "a curvature-designed head is not a code head: UG-32 and Appendix 1-4 do not apply";
  }
  out.thickness_sufficient = thickness >= required;
  return out;
}

VesselMeasures vessel_measures(const HeadPreset& preset, double radius, double length,
                               double thickness, double density, double straight_flange) {
  if (!(straight_flange >= 0.0 && 2 * straight_flange < length))
    throw InputError("vessel measures: straight flange " + number_text(straight_flange) +
                     " mm, expected >= 0 and below half the length " + number_text(length) + " mm");
  const HeadMeasures dish = head_measures(preset, radius);
  const HeadMeasures shell = cylinder_measures(radius, length);
  const double dish_metal = head_metal_volume(preset, radius, thickness);
  VesselMeasures out;
  out.straight_flange = straight_flange;
  out.head_volume = dish.volume;
  out.head_area = dish.area;
  out.head_metal_volume = dish_metal;
  if (straight_flange > 0.0) {  // π R² f, 2π R f and the wall's ring
    const HeadMeasures flange = cylinder_measures(radius, straight_flange);
    out.head_volume += flange.volume;
    out.head_area += flange.area;
    out.head_metal_volume += cylinder_metal_volume(radius, straight_flange, thickness);
  }
  out.vessel_volume = 2 * dish.volume + shell.volume;
  out.metal_volume = 2 * dish_metal + cylinder_metal_volume(radius, length, thickness);
  out.density = density;
  out.head_weight = metal_weight(out.head_metal_volume, density);
  out.weight = metal_weight(out.metal_volume, density);
  return out;
}

}  // namespace polarform
