// The cam's key numbers at a glance: stroke, the SVAJ extremes with where they occur, the largest
// pressure angle against the limit, the smallest radii of curvature, undercut ranges, the flat
// face's width, and every continuity issue between segments — red where a limit is broken.
#pragma once

#include "jobs/cam/cam_job.h"
#include "ui/studio/cam_view_settings.h"

namespace polarform::studio {

void draw_cam_summary(const CamDesignStage& design, const CamAnalysisStage& analysis,
                      const CamViewSettings& view);

}  // namespace polarform::studio
