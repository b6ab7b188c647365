// A vessel design against the pressure-vessel code and its closed-form measures: the cylinder and,
// for an exact standard head, the head checked by ASME VIII-1 (code_rules.h) at the design's
// pressure and wall thickness; the head's and the vessel's inside volume, inner area and metal
// weight (head_measures.h). The vessel's radius is its inside radius.
#pragma once

#include <optional>
#include <string>

#include "designers/vessel/code_rules.h"
#include "designers/vessel/head_preset.h"

namespace polarform {

// What the code check needs beyond the design: the material's allowable stress, the joints'
// efficiency and the corrosion allowance.
struct CodeInputs {
  double allowable_stress = 0.0;     // S, MPa
  double joint_efficiency = 1.0;     // E
  double corrosion_allowance = 0.0;  // c, mm

  bool operator==(const CodeInputs&) const = default;
};

struct VesselCodeCheck {
  CodeCheck shell;
  std::optional<CodeCheck> head;      // an exact standard head only
  std::string head_note;              // why there is no head check, when there is none
  double mawp = 0.0;                  // MPa: the smaller of the shell's and the head's
  bool thickness_sufficient = false;  // the wall is at least every required thickness
};

// Throws InputError for bad code inputs (code_rules.h).
VesselCodeCheck check_vessel_code(const CodeInputs& code, double radius, double thickness,
                                  double pressure, const std::optional<HeadPreset>& exact_head);

struct VesselMeasures {
  // One formed head: the dished part above its tangent line and its straight flange (the
  // cylinder of the flange length below the tangent line, which is part of the head as formed
  // and of the tangent-to-tangent length), mm³ and mm² of the inner surface; its metal, mm³, and
  // weight, kg.
  double head_volume = 0.0, head_area = 0.0;
  double head_metal_volume = 0.0, head_weight = 0.0;
  double straight_flange = 0.0;               // mm
  double vessel_volume = 0.0;                 // two heads and the cylinder between them, mm³
  double metal_volume = 0.0;                  // two heads and the cylinder, wall t, mm³
  double density = 0.0;                       // kg/m³
  double weight = 0.0;                        // kg
};

// The measures of a vessel with two exact standard heads of `preset` on a cylinder of `radius`
// and tangent-to-tangent `length`, wall `thickness`, of a material of `density` kg/m³, each head
// formed with a straight flange of `straight_flange` mm (0 <= 2 × it < length, else InputError).
VesselMeasures vessel_measures(const HeadPreset& preset, double radius, double length,
                               double thickness, double density, double straight_flange = 0.0);

}  // namespace polarform
