// The scanned-patch job of `polarform patch` (Piegl & Tiller 2001): a scan is read, its boundary
// made from a boundary file of four polylines or from the border of a structured grid, and the
// patch fitted (designers/patch). Computing writes nothing; patch_outputs.h writes the bundle.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "designers/patch/boundary_input.h"
#include "designers/patch/patch_fit.h"
#include "jobs/interrogation/surface_interrogation.h"

namespace polarform {

struct PatchJobOptions {
  std::optional<std::filesystem::path> boundary_file;  // --boundary
  std::optional<std::pair<int, int>> grid;             // --grid ROWS,COLS
  PatchFitOptions fit;
  std::optional<CurvatureQuantity> interrogate;  // --interrogate: curvature maps, reflection lines
  bool skip_bad = false;
};

struct PatchJobResult {
  std::filesystem::path input;
  std::string boundary_source;  // "boundary file NAME" or "grid ROWS × COLS border"
  Eigen::Matrix3Xd points;      // the data: inside the boundary
  std::size_t dropped = 0;
  FittedBoundary boundary;
  PatchFit patch;
  std::optional<SurfaceInterrogation> interrogation;
  double read_seconds = 0.0, boundary_seconds = 0.0, total_seconds = 0.0;
  bool tolerance_met() const { return patch.fit.tolerance_met; }
};

// Throws InputError for an unreadable scan or boundary file, neither or both of --boundary and
// --grid, or bad options; NumericalError when a stage cannot complete.
PatchJobResult run_patch_job(const std::filesystem::path& scan, const PatchJobOptions& options);

}  // namespace polarform
