// The cam job: everything `polarform cam` and the studio compute for a cam project — the motion
// program and its continuity diagnostics, the cam geometry and analyses, the exact NURBS profile
// (plate cam contour, or cylindrical cam track centre line) with its measured error, and the
// degree-limited profile for consumers that cap the degree. Computing writes nothing.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/continuity.h"
#include "designers/cam/groove_surface.h"
#include "designers/convert/degree_limited.h"
#include "designers/convert/polar_conversion.h"
#include "jobs/project/cam_project.h"

namespace polarform {

struct CamJobOptions {
  int analysis_angles = 720;  // grid of the analyses and plots over one revolution
  int limited_degree = 3;     // degree of the degree-limited profile (profile_deg3.dxf)
  bool with_limited = true;   // compute the degree-limited profile
};

struct CamJobResult {
  CamJobResult(CamProject p, CamProgram prog) : project(std::move(p)), program(std::move(prog)) {}

  CamProject project;
  CamProgram program;
  std::vector<ContinuityIssue> continuity;
  std::vector<double> angles;                  // the analysis grid, rad
  std::vector<Kinematics> kinematics;          // at each grid angle, time units from rpm
  std::optional<PlateCam> plate;               // plate cams
  std::optional<CamAnalysis> analysis;         // plate cams
  std::optional<BarrelCam> barrel;             // cylindrical cams
  std::vector<double> barrel_pressure_angle;   // cylindrical cams: at the pitch radius, rad
  PolarFunction profile_function;  // contour R(ψ) (plate) or track height + offset (cylindrical)
  PolarConversion conversion;      // of profile_function
  NurbsCurve2d profile;            // plate cams: the exact-degree contour
  NurbsCurve3d track;              // cylindrical cams: the track centre line on the cylinder
  double track_offset = 0.0;       // cylindrical: conversion of z + offset (kept positive)
  // Cylindrical cams with a groove depth: the walls on the −z and +z side of the track, within
  // the conversion tolerance.
  std::vector<GrooveSurface> groove;
  std::optional<LimitedCurve> limited;  // plate cams: degree-limited contour
  // Plate cams whose exact degree exceeds the project's max-degree: the profile to export instead.
  std::optional<LimitedCurve> capped;
  // What the job left out and why (e.g. a degree-limited profile that cannot meet the tolerance).
  std::vector<std::string> warnings;
  double seconds = 0.0;            // wall time of the computation
};

// What the job converts: the plate cam's contour R(ψ), or the cylindrical cam's track height
// z(φ) + track_height_offset(design) (the converter takes positive polar functions).
PolarFunction cam_profile_function(const CamDesign& design);
double track_height_offset(const CamDesign& design);

// Throws InputError (bad design, undercut, …) or NumericalError with a message naming the cause.
CamJobResult run_cam_job(const CamProject& project, const CamJobOptions& options = {});

}  // namespace polarform
