#include "jobs/vessel/vessel_job.h"

#include <chrono>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

// Bae 2002, §5.2: synthesise R(θ), convert it with quasi-uniform base arcs (§5.1), revolve it.
VesselJobResult run_vessel_job(const VesselProject& project) {
  const auto start = Clock::now();
  if (!(project.tolerance >= kMinTolerance))
    throw InputError("conversion tolerance " + format_round_trip(project.tolerance) +
                     " mm: expected >= " + format_round_trip(kMinTolerance) + " mm");
  VesselJobResult r;
  r.project = project;
  r.design = to_design(project);
  r.solution = solve_vessel(r.design);
  r.seconds.solve = seconds_since(start);

  const auto converting = Clock::now();
  ConversionOptions options;
  options.tolerance = project.tolerance;
  r.conversion = convert_polar_function(r.solution.profile, options);
  r.seconds.convert = seconds_since(converting);

  const auto revolving = Clock::now();
  r.surfaces = vessel_surfaces(r.conversion.curve, r.design.length);
  r.seconds.revolve = seconds_since(revolving);
  r.seconds.total = seconds_since(start);
  return r;
}

}  // namespace polarform
