// The viz job's preview (preview.svg): the measured values along the grid's rows (value against
// θ at four polar angles φ or heights z) and columns (against φ or z at four azimuths), each with
// the fitted F along the matching iso-parameter curve of S = (s·F + d)·B (Bae 2002, eq. (5.6)),
// which lies at one φ (or z) for fixed u and at one θ for fixed v because B is a surface of
// revolution.
#pragma once

#include "export/figure.h"
#include "jobs/viz/viz_job.h"

namespace polarform {

Figure viz_preview_figure(const VizJobResult& r);

}  // namespace polarform
