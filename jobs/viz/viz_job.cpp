#include "jobs/viz/viz_job.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/error.h"
#include "src/fit/function_fit.h"
#include "src/fit/stage_times.h"

namespace polarform {

VizJobResult run_viz_job(ScalarGrid grid, const std::string& name, const VizJobOptions& o) {
  StageClock clock;
  if (!(o.scale != 0.0) || !std::isfinite(o.scale))
    throw InputError("--scale must be a finite non-zero number");
  if (o.offset && !std::isfinite(*o.offset)) throw InputError("--offset must be a finite number");
  if (o.threads < 1) throw InputError("threads must be at least 1");
  VizJobResult r;
  r.input = name;
  r.grid = std::move(grid);
  r.scale = o.scale;
  const Eigen::VectorXd sp = o.scale * r.grid.value;
  const double lo = sp.minCoeff(), hi = sp.maxCoeff();
  std::ostringstream why;
  why.precision(6);
  if (o.offset) {
    r.offset = *o.offset;
    why << "given";
  } else if (lo > 0) {
    r.offset = 0.0;
    why << "every scaled value is positive: the radius is the value";
  } else {
    // A constant field has no range: its magnitude (or 1) sets the radius instead.
    const double radius = hi > lo ? 0.5 * (hi - lo) : std::max(std::abs(lo), 1.0);
    r.offset = radius - lo;
    why << "the smallest scaled value " << lo << " is not positive: shifted to radius " << radius;
  }
  r.offset_reason = why.str();
  ScalarFieldOptions so;
  if (o.degree) so.function.degree_u = o.degree->first, so.function.degree_v = o.degree->second;
  if (o.ctrl) check_control_net_size(o.ctrl->first, o.ctrl->second, "--ctrl");
  if (o.ctrl) so.function.size_u = o.ctrl->first, so.function.size_v = o.ctrl->second;
  so.function.threads = o.threads;
  so.scale = r.scale;
  so.offset = r.offset;
  so.closure = o.closure;
  r.field = naming_input(name, [&] {
    return r.grid.setup == GridSetup::spherical
               ? visualize_spherical(r.grid.value, r.grid.phi, r.grid.theta, so)
               : visualize_cylindrical(r.grid.value, r.grid.theta, r.grid.z, so);
  });
  r.seconds = clock.lap();
  return r;
}

VizJobResult run_viz_job(const std::filesystem::path& grid, const VizJobOptions& o) {
  StageClock clock;
  ScalarGrid g = read_scalar_grid(grid);
  const double read = clock.lap();
  VizJobResult r = run_viz_job(std::move(g), grid.string(), o);
  r.seconds += read;
  return r;
}

}  // namespace polarform
