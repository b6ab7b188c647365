// The fit project file: a scan and how to fit it, as XML, so a fit can be repeated, shared and
// opened in the studio. Lengths in mm; the scan path is relative to the project file's folder
// (or absolute). Reading names file:line:attribute for every bad value and warns about unknown
// fields; writing is atomic, and a saved project loads back exactly.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "jobs/project/unknown_names.h"
#include "src/fit/function_fit.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/revolution_test.h"
#include "src/fit/spherical_fit.h"

namespace polarform {

// The fit job's method. auto: a planar cloud is a profile (polar curve), else the best-fit
// quadric decides between spherical and cylindrical.
enum class FitJobMethod { automatic, polar, spherical, cylindrical };

struct FitProject {
  std::filesystem::path scan;  // as written in the file
  FitJobMethod method = FitJobMethod::automatic;
  Closure closure = Closure::automatic;
  std::optional<PoleTreatment> pole;          // both poles of a spherical fit; else automatic
  std::optional<std::pair<int, int>> degree;  // of F: (u ↔ φ or z, v ↔ θ)
  std::optional<std::pair<int, int>> ctrl;    // F's control net
  std::optional<double> tolerance;            // mm, instead of ctrl: refine until met
  ToleranceMeasure measure = ToleranceMeasure::max;
  std::optional<Eigen::Vector3d> center;  // frame origin / polar centre, mm
  std::optional<Eigen::Vector3d> axis;    // frame axis k / a profile's plane normal
  bool skip_bad = false;
  bool reject_outliers = false;  // leave outliers out of the fit instead of refusing the scan
  // Fairing of F (Bae 2002, §3.4.2): how λ is chosen, and the weight of the fixed / relative rule.
  FairnessOptions::Mode fairness = FairnessOptions::Mode::relative;
  double fairness_weight = 1e-7;
  ArcKind base = ArcKind::rqb;  // the base circles' arcs: RQB or quasi-uniform quartic
  // F constant around the axis: decided by the F-test (auto), or asked for (yes / no).
  RevolutionMode revolution = RevolutionMode::automatic;

  bool operator==(const FitProject&) const = default;
};

// "fixed", "relative" or "gcv": the word of a fairing rule in fit projects and reports.
const char* fairness_word(FairnessOptions::Mode mode);
// "auto", "none", "g0", "g1" or "cap": the word of a pole treatment in fit projects and reports.
const char* pole_word(PoleTreatment pole);

// The scan's path: `project.scan` taken relative to the folder of `project_file`.
std::filesystem::path scan_path(const FitProject& project,
                                const std::filesystem::path& project_file);

// Reads <polarform version="1"><fit …/></polarform>, or a bare <fit> root:
//   <fit scan="cloud.ply" method="auto|polar|spherical|cylindrical" closed="auto|yes|no"
//        pole="none|g1|cap" degree="3,3" ctrl="12,12" tolerance="mm"
//        tolerance-measure="max|p99|p95|rms" center="x,y,z" axis="x,y,z" skip-bad="false"
//        reject-outliers="false" fairness="fixed|relative|gcv" lambda="1e-7" base="rqb|quartic"
//        revolution="auto|yes|no"/>
// Throws InputError "file:line: <fit> attribute 'x': expected …" for bad values, and for unknown
// attributes or elements, which UnknownNames::warn turns into warnings.
FitProject read_fit_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                            UnknownNames policy = UnknownNames::refuse);
FitProject parse_fit_project(const std::string& text, const std::string& file,
                             std::vector<std::string>& warnings,
                             UnknownNames policy = UnknownNames::refuse);

// The project as XML (numbers in their shortest exact form) and saved atomically.
std::string fit_project_xml(const FitProject& project);
void write_fit_project(const FitProject& project, const std::filesystem::path& file);

}  // namespace polarform
