// The visualisation job of `polarform viz` (Bae 2002, §5.3): a grid of values measured on a
// spherical or cylindrical set-up is fitted by a single-valued F and shown as the NURBS surface
// S = (s·F + d)·B (eq. (5.6)) whose radius is the value, each control point carrying the value at
// its parameters for colouring. Computing writes nothing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "src/fit/scalar_field_surface.h"
#include "src/io/grid_reader.h"

namespace polarform {

struct VizJobOptions {
  std::optional<std::pair<int, int>> degree;  // of F (u ↔ φ or z, v ↔ θ)
  std::optional<std::pair<int, int>> ctrl;    // F's control net
  double scale = 1.0;                         // s of (5.6), non-zero
  std::optional<double> offset;               // d of (5.6); default: see run_viz_job
  Closure closure = Closure::automatic;
  int threads = 2;
};

struct VizJobResult {
  std::filesystem::path input;
  ScalarGrid grid;
  ScalarFieldSurface field;
  double scale = 1.0, offset = 0.0;
  std::string offset_reason;
  double seconds = 0.0;
};

// The default offset is 0 when every s·p is positive, else the one that puts the smallest s·p at
// half the range of s·p from the centre (a radius must stay positive to read as a value; a
// constant field goes to radius max(|s·p|, 1)). Throws InputError for a bad file or options.
VizJobResult run_viz_job(const std::filesystem::path& grid, const VizJobOptions& options = {});
VizJobResult run_viz_job(ScalarGrid grid, const std::string& name,
                         const VizJobOptions& options = {});

}  // namespace polarform
