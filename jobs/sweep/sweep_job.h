// The sweep-recovery job of `polarform sweep` (Kantz 2003): a scan or mesh is read, its kind is
// decided and the swept surface recovered — today the surface of revolution (spec K11); the
// extrusion and section kinds are not implemented yet and are refused by name. Computing writes
// nothing; sweep_outputs.h writes the bundle.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "designers/sweep/revolution_recovery.h"
#include "jobs/interrogation/surface_interrogation.h"

namespace polarform {

enum class SweepKind { automatic, revolution, extrusion };

struct SweepJobOptions {
  SweepKind kind = SweepKind::automatic;
  std::optional<Eigen::Vector3d> axis, center;  // --axis, --center
  double tolerance = 0.0;                       // <= 0: 1e-4 of the size
  int degree = 3;
  double corner_angle_deg = 30.0;
  int threads = 2;
  bool skip_bad = false;
  std::optional<CurvatureQuantity> interrogate;  // curvature maps, reflection lines
};

struct SweepJobResult {
  std::filesystem::path input;
  Eigen::Matrix3Xd points;
  std::size_t dropped = 0;
  std::string kind = "revolution";
  std::string reason;  // why this kind, with the numbers that decided it
  RevolutionRecovery revolution;
  std::optional<SurfaceInterrogation> interrogation;
  double read_seconds = 0.0, total_seconds = 0.0;
  bool tolerance_met() const { return revolution.error.max <= revolution.tolerance; }
};

// Throws InputError for an unreadable file or bad options (a zero axis, --center without --axis,
// the kind extrusion), NumericalError when no profile can be recovered.
SweepJobResult run_sweep_job(const std::filesystem::path& scan,
                             const SweepJobOptions& options = {});

}  // namespace polarform
