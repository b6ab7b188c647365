#include "jobs/vessel/vessel_job.h"

#include <chrono>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

namespace {

using Clock = std::chrono::steady_clock;

// Samples per conic arc at which an exact head's meridian is measured against its closed form.
constexpr int kExactHeadSamples = 2000;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void check_tolerance(const VesselProject& project) {
  if (!(project.tolerance >= kMinTolerance))
    throw InputError("conversion tolerance " + format_round_trip(project.tolerance) +
                     " mm: expected >= " + format_round_trip(kMinTolerance) + " mm");
}

}  // namespace

// Bae 2002, §5.2: synthesise R(θ) from the prescribed curvatures under the end conditions (5.5).
VesselSolveStage solve_vessel_head(const VesselProject& project) {
  const auto start = Clock::now();
  VesselSolveStage s;
  s.project = project;
  s.design = to_design(project);
  s.solution = solve_vessel(s.design);
  s.seconds = seconds_since(start);
  return s;
}

// Bae 2002, §5.1: convert R(θ) with quasi-uniform base arcs (an exact head is already NURBS),
// then revolve it.
VesselConversionStage convert_vessel_head(const VesselSolveStage& solved) {
  check_tolerance(solved.project);
  const auto converting = Clock::now();
  VesselConversionStage c;
  if (const std::optional<ExactHead>& exact = solved.solution.exact) {
    c.profile = exact->meridian;
    c.arcs = exact->arcs;
    c.max_radial_error = exact_head_deviation(exact->meridian, exact->shape, kExactHeadSamples);
  } else {
    ConversionOptions options;
    options.tolerance = solved.project.tolerance;
    options.compaction = solved.project.compaction;
    c.conversion = convert_polar_function(solved.solution.profile, options);
    c.profile = c.conversion->curve;
    c.arcs = static_cast<int>(c.conversion->arcs.size());
    c.max_radial_error = c.conversion->max_radial_error;
  }
  c.convert_seconds = seconds_since(converting);
  const auto revolving = Clock::now();
  c.surfaces = vessel_surfaces(c.profile, solved.design.length);
  c.revolve_seconds = seconds_since(revolving);
  return c;
}

VesselJobResult run_vessel_job(const VesselProject& project) {
  const auto start = Clock::now();
  check_tolerance(project);  // before the synthesis's work
  VesselJobResult r;
  r.solved = solve_vessel_head(project);
  r.converted = convert_vessel_head(r.solved);
  r.seconds = {r.solved.seconds, r.converted.convert_seconds, r.converted.revolve_seconds,
               seconds_since(start)};
  return r;
}

}  // namespace polarform
