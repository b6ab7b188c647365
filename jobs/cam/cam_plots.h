// The cam job's figures, built from its stages so that the studio can show them while a design is
// edited and the output bundle can write them as SVG: SVAJ (stacked panels against cam angle,
// with segment boundaries and every continuity issue), analyses (pressure angle, radii of
// curvature, undercut; the cylindrical cam's pressure angle and track height), the profile itself
// (contour, control polygon, base and pitch circles; the developed track) and the measured
// conversion error along the profile.
#pragma once

#include <optional>

#include "export/figure.h"
#include "jobs/cam/cam_job.h"

namespace polarform {

struct SvajFigureOptions {
  bool time_units = true;       // v [mm/s], a [m/s²], j [m/s³] at the cam's speed; else per rad
  bool pressure_panel = false;  // a fifth panel: the pressure angle
  std::optional<double> pressure_angle_limit;  // rad: ± lines on that panel (plate cams)
  bool draggable_boundaries = false;           // boundary k (start of segment k) carries handle k
};

Figure svaj_figure(const CamDesignStage& design, const CamAnalysisStage& analysis,
                   const SvajFigureOptions& options = {});
Figure analysis_figure(const CamDesignStage& design, const CamAnalysisStage& analysis);
Figure profile_figure(const CamDesignStage& design, const CamAnalysisStage& analysis,
                      const CamConversionStage& conversion);
Figure conversion_error_figure(const CamConversionStage& conversion, bool log_scale = false);
// The follower's dynamics against cam angle (needs analysis.dynamics): force.svg, the contact
// force with the zero line below which the follower jumps; torque.svg, the camshaft torque;
// stress.svg, the contact stress.
Figure contact_force_figure(const CamDesignStage& design, const CamAnalysisStage& analysis);
Figure camshaft_torque_figure(const CamDesignStage& design, const CamAnalysisStage& analysis);
Figure contact_stress_figure(const CamDesignStage& design, const CamAnalysisStage& analysis);

}  // namespace polarform
