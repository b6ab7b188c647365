// The figures of a patch job: the quad blanket of the base surface (its parameter lines U × V and
// the blanket seen along the maximum-area normal, P&T Fig. 5–6) and the deviation of every point
// against its parameters (the preview).
#pragma once

#include "export/figure.h"
#include "jobs/patch/patch_job.h"

namespace polarform {

Figure patch_decomposition_figure(const PatchJobResult& r);
Figure patch_preview_figure(const PatchJobResult& r);

}  // namespace polarform
