#include "jobs/patch/patch_job.h"

#include <chrono>

#include "src/error.h"
#include "src/io/boundary_csv.h"
#include "src/io/point_cloud.h"

namespace polarform {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

PatchJobResult run_patch_job(const std::filesystem::path& scan, const PatchJobOptions& o) {
  if (o.boundary_file.has_value() == o.grid.has_value())
    throw InputError("give the boundary: either --boundary CURVES.csv or --grid ROWS,COLS");
  const auto t0 = std::chrono::steady_clock::now();
  PatchJobResult r;
  r.input = scan;
  ReadOptions ro;
  ro.skip_bad = o.skip_bad;
  PointCloud cloud = read_point_cloud(scan, ro);
  r.dropped = cloud.dropped;
  r.read_seconds = seconds_since(t0);
  BoundaryFitOptions bo;
  bo.degree = std::max(o.fit.degree_u, o.fit.degree_v);
  if (o.fit.tolerance > 0) bo.tolerance = 0.5 * o.fit.tolerance;
  if (o.grid) {
    if (r.dropped > 0)
      throw InputError(scan.string() + ": --grid needs every grid point, but " +
                       std::to_string(r.dropped) + " record(s) were dropped by --skip-bad");
    const StructuredGrid g = split_structured_grid(cloud.points, o.grid->first, o.grid->second);
    r.boundary = fit_boundary_polylines(g.polylines, bo);
    r.points.resize(3, static_cast<Eigen::Index>(g.inside.size()));
    for (std::size_t k = 0; k < g.inside.size(); ++k)
      r.points.col(static_cast<Eigen::Index>(k)) = cloud.points.col(g.inside[k]);
    r.boundary_source = "border of the " + std::to_string(o.grid->first) + " × " +
                        std::to_string(o.grid->second) + " grid";
  } else {
    try {
      r.boundary = fit_boundary_polylines(read_boundary_csv(*o.boundary_file).curves, bo);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.starts_with(o.boundary_file->string())
                           ? what
                           : o.boundary_file->string() + ": " + what);
    }
    r.points = std::move(cloud.points);
    r.boundary_source = "boundary file " + o.boundary_file->filename().string();
  }
  r.boundary_seconds = seconds_since(t0) - r.read_seconds;
  try {
    r.patch = fit_patch(r.points, r.boundary.boundary, o.fit);
  } catch (const InputError& e) {
    throw InputError(scan.string() + ": " + e.what());
  }
  if (o.interrogate) r.interrogation = interrogate_surfaces({r.patch.fit.surface}, *o.interrogate);
  r.total_seconds = seconds_since(t0);
  return r;
}

}  // namespace polarform
