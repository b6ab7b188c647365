// The sweep-recovery job of `polarform sweep` (Kantz 2003): a scan or mesh is read, its kind is
// decided (designers/sweep/sweep_kind.h; both are recovered and the better kept when the evidence
// allows both or neither) and the swept surface recovered — the surface of revolution (spec K11)
// or the extrusion (spec K10); or, when asked, the skin of sections along a straight or curved
// spine (specs K12, M9). Computing writes nothing; sweep_outputs.h writes the bundle.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "designers/sweep/extrusion_recovery.h"
#include "designers/sweep/revolution_recovery.h"
#include "designers/sweep/section_recovery.h"
#include "designers/sweep/sweep_kind.h"
#include "jobs/interrogation/surface_interrogation.h"

namespace polarform {

enum class SweepKind { automatic, revolution, extrusion, sections };

struct SweepJobOptions {
  SweepKind kind = SweepKind::automatic;
  std::optional<Eigen::Vector3d> axis, center;  // --axis, --center (an extrusion: its direction)
  double tolerance = 0.0;                       // <= 0: 1e-4 of the size
  int degree = 3;
  double corner_angle_deg = 30.0;
  int threads = 2;
  bool skip_bad = false;
  std::optional<CurvatureQuantity> interrogate;  // curvature maps, reflection lines
  // The kind sections: a fixed count of sections (0: adaptive slicing) and the spine's shape.
  int sections = 0;
  SpineShape spine = SpineShape::automatic;
};

struct SweepJobResult {
  std::filesystem::path input;
  Eigen::Matrix3Xd points;
  std::size_t dropped = 0;
  std::optional<SweepKindEvidence> evidence;  // decided automatically
  std::string reason;  // why this kind, with the numbers that decided it
  // The kind kept is the one present; both are present when both were recovered and compared
  // (the other one is then kept for the report only).
  std::optional<RevolutionRecovery> revolution;
  std::optional<ExtrusionRecovery> extrusion;
  std::optional<SectionRecovery> sections;  // only when asked (--kind sections)
  bool is_extrusion = false, is_sections = false;
  std::string kind() const {
    return is_sections ? "sections" : is_extrusion ? "extrusion" : "revolution";
  }
  const SweptFit& fit() const;  // the kept recovery
  std::optional<SurfaceInterrogation> interrogation;
  double read_seconds = 0.0, total_seconds = 0.0;
  bool tolerance_met() const { return fit().error.max <= fit().tolerance; }
};

// Throws InputError for an unreadable file or bad options (a zero axis, --center without --axis or
// with the kind extrusion, --axis with the kind sections, --sections with another kind, a section
// that is not closed or star-shaped), NumericalError when no profile can be recovered.
SweepJobResult run_sweep_job(const std::filesystem::path& scan,
                             const SweepJobOptions& options = {});

}  // namespace polarform
