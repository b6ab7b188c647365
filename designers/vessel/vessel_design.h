// A pressure-vessel design and everything the vessel job needs from it before conversion: the
// synthesised head R(θ) (Bae 2002, §5.2) as a PolarFunction for the converter, its curvature, the
// junction and apex geometry, the membrane stresses along the meridian, and the comparison with a
// classical preset head (its exact profile, curvature jumps and stresses). The surfaces follow from
// the converted profile through vessel_surfaces (vessel_surfaces.h, which defines the geometry).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "designers/convert/polar_function.h"
#include "designers/vessel/curvature_synthesis.h"
#include "designers/vessel/edge_bending.h"
#include "designers/vessel/exact_head.h"
#include "designers/vessel/flat_plate.h"
#include "designers/vessel/head_depth_comparison.h"
#include "designers/vessel/head_measures.h"
#include "designers/vessel/head_preset.h"
#include "designers/vessel/membrane_stress.h"
#include "designers/vessel/smoothing_choice.h"
#include "designers/vessel/stress_optimal_head.h"
#include "designers/vessel/vessel_code_check.h"

namespace polarform {

// What the head is: synthesised from prescribed curvatures (Bae 2002, §5.2), the preset head
// itself, exactly (exact_head.h), or the head of a given depth with the smallest peak membrane
// stress (stress_optimal_head.h).
enum class HeadDesign { curvature, exact, minimum_stress };

// "curvature", "exact", "minimum-stress" (the words of the project file).
const char* head_design_name(HeadDesign design);

struct VesselDesign {
  double radius = 0.0;     // cylinder radius, mm
  double length = 0.0;     // cylinder length between the junctions, mm
  double thickness = 0.0;  // wall thickness, mm
  double pressure = 0.0;   // internal pressure, MPa
  // Prescribed curvatures; when empty, `preset_targets` samples of the preset's distribution
  // (the curvature-continuous alternative to the preset). With both, the preset is only compared.
  std::vector<CurvatureTarget> targets;
  std::optional<EndCondition> end_a;  // θ = 0; absent: EndCondition::thesis_default(radius)
  std::optional<EndCondition> end_b;  // θ = π; the same
  SynthesisSettings synthesis;
  std::optional<HeadPreset> preset;
  int preset_targets = 48;
  // exact: the preset head itself (needs a preset and no targets; end conditions and synthesis
  // settings are not used).
  HeadDesign head_design = HeadDesign::curvature;
  // minimum_stress: the head's depth, mm (absent: the preset's depth), and its meridian's
  // curvature at the junctions, 1/mm (absent: free; 0: curvature-continuous with the cylinder).
  // curvature: the depth, when given, is imposed as R(π/2) = depth.
  std::optional<double> depth;
  // curvature: the volume the head encloses with its junction plane, mm³ (head_volume.h).
  std::optional<double> volume;
  std::optional<double> junction_kappa;
  std::optional<CodeInputs> code;  // check the wall by ASME VIII-1 (vessel_code_check.h)
  double density = 7850.0;         // kg/m³ of the wall material (steel), for the weight
  double straight_flange = 0.0;    // mm: each exact head's straight flange (vessel_measures)
  double poisson = 0.3;            // Poisson's ratio ν of the wall (steel), for the edge bending

  bool operator==(const VesselDesign&) const = default;
};

struct CurvatureSample {
  double theta = 0.0;  // rad
  double kappa = 0.0;  // 1/mm
  double R = 0.0, dR = 0.0, d2R = 0.0;  // R(θ), mm, and its derivatives, mm/rad and mm/rad²
};

struct PresetComparison {
  HeadShape shape;
  std::vector<CurvatureSample> curvature;  // piece by piece: both one-sided values at every joint
  double max_deviation = 0.0;    // max |R_design − R_preset| over 1441 angles in [0, π], mm
  double deviation_angle = 0.0;  // rad
  StressProfile stresses;        // of the preset head
};

// A minimum-stress head with the standard heads of its depth under the same load.
struct MinimumStressDesign {
  StressOptimalSettings settings;  // the optimiser's, as run
  StressOptimalHead head;
  HeadStressSummary stresses;  // of the designed head, at the exact extrema
  DepthComparison same_depth;
};

struct VesselSolution {
  SynthesisResult synthesis;       // empty for an exact or minimum-stress head
  SmoothingChoice smoothing;       // how the synthesis's λ was chosen
  int placement_rounds = 0;        // syntheses run to place targets given by s or φ (else 1)
  std::optional<HeadMeasures> measures_of_design;  // a curvature or minimum-stress head's
                                                   // volume and inner area (head_volume.h)
  std::optional<ExactHead> exact;  // the exact head (HeadDesign::exact)
  std::optional<MinimumStressDesign> minimum_stress;  // HeadDesign::minimum_stress
  // R(θ) on [0, π] for the converter: exact = synthesis.profile; π/2 is a breakpoint so that the
  // apex, where vessel_surfaces splits the converted curve, is an arc junction.
  PolarFunction profile;
  // κ(θ) at 361 equal steps over [0, π]; an exact head's piece by piece, both one-sided values
  // at every joint.
  std::vector<CurvatureSample> curvature;
  double depth = 0.0;               // R(π/2), mm
  double junction_radius = 0.0;     // R(0), mm
  double junction_curvature = 0.0;  // κ(0), 1/mm (the cylinder's meridian has κ = 0)
  double junction_slope = 0.0;      // atan(R'(0)/R(0)), rad: the kink against the cylinder
  double apex_slope = 0.0;          // atan(R'(π/2)/R(π/2)), rad: non-zero is a cone point
  StressProfile stresses;           // of the designed head (the revolved A half) and cylinder
  // At the head's curvature jumps on the A half by edge theory: an exact head's junction and
  // knuckle joints, another head's junction (edge_bending.h).
  std::vector<EdgeBending> edge_bending;
  // A flat head's plate, which bends (flat_plate.h); its membrane stresses stop at the knuckle.
  std::optional<FlatPlateBending> flat_plate;
  std::optional<PresetComparison> preset;
  std::optional<VesselCodeCheck> code;     // with the design's code inputs
  std::optional<VesselMeasures> measures;  // an exact head: volumes, areas, weight
  std::vector<std::string> warnings;       // kinks, a radius mismatch, compressive hoop bands, code
};

// Throws InputError for a bad design (radius, length, thickness, pressure <= 0, no targets and no
// preset, an exact head without a preset or with targets, a minimum-stress head with targets or
// without a depth or preset, preset_targets < 1, and whatever
// synthesize_profile and head_shape reject) and passes on the synthesis's NumericalError.
VesselSolution solve_vessel(const VesselDesign& design);

// A B-spline R(θ) on [0, π] as the converter's input: exact, with the apex π/2 as breakpoint.
PolarFunction head_polar_function(const BSplineFunction& R);

// κ(θ) at count + 1 equal steps over [f.start, f.end] (count >= 1).
std::vector<CurvatureSample> sample_curvature(const PolarFunction& f, int count);

}  // namespace polarform
