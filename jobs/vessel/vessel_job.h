// The vessel job: everything `polarform vessel` and the studio compute for a vessel project, as a
// staged pipeline the studio runs in the background after every edit:
//   solve    the head R(θ) synthesised from prescribed curvatures (Bae 2002, §5.2) with its
//            residuals, and the membrane stresses of the design and of the preset it replaces;
//   convert  the exact NURBS profile within the tolerance with its measured error (§5.1) — or,
//            for an exact standard head, its degree-2 meridian measured against the closed
//            form — and the revolved head and vessel surfaces.
// The result value is what the studio shows and what the output bundle (vessel_outputs.h)
// writes. Computing writes nothing.
#pragma once

#include <optional>

#include "designers/convert/polar_conversion.h"
#include "designers/vessel/vessel_design.h"
#include "designers/vessel/vessel_surfaces.h"
#include "jobs/project/vessel_project.h"

namespace polarform {

struct VesselSolveStage {
  VesselProject project;    // as run (the tolerance after any override)
  VesselDesign design;      // to_design(project)
  VesselSolution solution;  // synthesis, curvature, stresses, preset comparison, warnings
  double seconds = 0.0;     // wall time of the synthesis and analyses
};

// Throws InputError for a bad design and passes on the synthesis's NumericalError (no
// convergence, R <= 0).
VesselSolveStage solve_vessel_head(const VesselProject& project);

struct VesselConversionStage {
  // A synthesised head's R(θ) converted over [0, π] within project.tolerance (Bae 2002, §5.1);
  // absent for an exact head, whose degree-2 meridian is exported as it is.
  std::optional<PolarConversion> conversion;
  NurbsCurve2d profile;           // what is exported and revolved: conversion->curve or the exact
  int arcs = 0;                   // base-circle arcs, or the exact head's conic arcs
  double max_radial_error = 0.0;  // measured |ρ − R(θ)| of `profile` against the head's R(θ), mm
  VesselSurfaces surfaces;        // revolved from `profile`
  double convert_seconds = 0.0, revolve_seconds = 0.0;
};

// Throws InputError (a tolerance below the converter's floor, surfaces that cannot be built) or
// NumericalError from the converter.
VesselConversionStage convert_vessel_head(const VesselSolveStage& solved);

struct VesselJobTimings {  // wall time, seconds
  double solve = 0.0;    // synthesis and analyses (curvature, stresses, preset comparison)
  double convert = 0.0;  // R(θ) → NURBS to the tolerance, measured
  double revolve = 0.0;  // head, cylinder and far-head surfaces
  double total = 0.0;
};

struct VesselJobResult {
  VesselSolveStage solved;
  VesselConversionStage converted;
  VesselJobTimings seconds;
};

// The tolerance is checked first; then both stages run.
VesselJobResult run_vessel_job(const VesselProject& project);

}  // namespace polarform
