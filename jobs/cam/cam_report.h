// The cam job's report.json (field names in docs/file-formats.md), built stage by stage so that
// the studio can show the same fields for the stages it has computed: the design (cam, segments,
// continuity), the conversion (tolerance, arcs, degree, measured errors, groove walls), the
// analyses (pressure angle, radii of curvature, undercut, SVAJ extremes) and the profile extras
// (warnings, degree-limited and capped profiles).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "jobs/cam/cam_job.h"

namespace polarform {

// The report's fields of the given stages (the conversion's only when there is one), in the
// report's order, without the version, command, files and timing.
nlohmann::ordered_json cam_report_fields(const CamDesignStage& design,
                                         const CamAnalysisStage& analysis,
                                         const CamConversionStage* conversion);

// The whole report of a finished job ("feasible": true).
nlohmann::ordered_json cam_report_json(const CamJobResult& r,
                                       const std::vector<std::string>& files);

// The report of an infeasible design: "feasible": false, the reason, and the design's and the
// analyses' fields (no conversion).
nlohmann::ordered_json cam_infeasible_report_json(const InfeasibleCam& cam,
                                                  const std::vector<std::string>& files);

}  // namespace polarform
