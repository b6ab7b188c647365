// The vessel job's report.json (field names in docs/cli-vessel.md), built stage by stage so that
// the studio shows the same fields for a solve that is not (or cannot be) converted: the vessel,
// the synthesis with its targets and end conditions, the head, the conversion and surfaces, the
// membrane stresses and the preset comparison.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "jobs/vessel/vessel_job.h"

namespace polarform {

// "mm", "mm/rad" or "mm/rad^2" for an end condition named "R(0)", "R'(π)", "R''(0)", …
std::string condition_unit(const std::string& name);

// The report's fields of the solve and, when there is one, the conversion, in the report's order,
// without the version, command, timings and files.
nlohmann::ordered_json vessel_report_fields(const VesselSolveStage& solved,
                                            const VesselConversionStage* converted);

// The whole report of a finished job.
nlohmann::ordered_json vessel_report_json(const VesselJobResult& r,
                                          const std::vector<std::string>& files);

}  // namespace polarform
