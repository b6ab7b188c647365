// The study job's figures: control points and base-circle arcs of the NURBS profile against the
// tolerance for the quasi-uniform quartic base, the RQB base, a cubic through sampled points, the
// compacted exact form, the degree-3 profile and (with peers) Open CASCADE's fits, with our
// control points over the best peer's (study.svg), and the max angle deviation of one base arc
// against its angle (Bae 2002, Fig. 5.4; deviation.svg). The studio's study workspace shows the
// same figures.
#pragma once

#include <string>

#include "export/figure.h"
#include "jobs/study/study_job.h"

namespace polarform {

Figure study_figure(const StudyJobResult& r, const std::string& design_name);
Figure deviation_figure(const StudyJobResult& r);

}  // namespace polarform
