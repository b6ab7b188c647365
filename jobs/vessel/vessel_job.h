// The vessel job: everything `polarform vessel` and the studio compute for a vessel project — the
// head R(θ) synthesised from prescribed curvatures (Bae 2002, §5.2) with its residuals, the exact
// NURBS profile converted to the tolerance with its measured error, the revolved head and vessel
// surfaces, and the membrane stresses of the design and of the preset it replaces. Computing
// writes nothing.
#pragma once

#include "designers/convert/polar_conversion.h"
#include "designers/vessel/vessel_design.h"
#include "designers/vessel/vessel_surfaces.h"
#include "jobs/project/vessel_project.h"

namespace polarform {

struct VesselJobTimings {  // wall time, seconds
  double solve = 0.0;    // synthesis and analyses (curvature, stresses, preset comparison)
  double convert = 0.0;  // R(θ) → NURBS to the tolerance, measured
  double revolve = 0.0;  // head, cylinder and far-head surfaces
  double total = 0.0;
};

struct VesselJobResult {
  VesselProject project;       // as run (the tolerance after any override)
  VesselDesign design;         // to_design(project)
  VesselSolution solution;     // synthesis, curvature, stresses, preset comparison, warnings
  PolarConversion conversion;  // of solution.profile over [0, π] to project.tolerance
  VesselSurfaces surfaces;     // revolved from conversion.curve
  VesselJobTimings seconds;
};

// Throws InputError for a bad design (whatever solve_vessel, the converter and vessel_surfaces
// reject) and passes on the synthesis's NumericalError (no convergence, R <= 0).
VesselJobResult run_vessel_job(const VesselProject& project);

}  // namespace polarform
