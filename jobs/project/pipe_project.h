// The pipe project file: a spine given as a NURBS curve (control points with weights, degree,
// knots) and the pipe's options, as XML, for `polarform pipe SPINE.xml` (MIT 13.472J §8.3–8.4).
// Reading names file:line:attribute for every bad value and refuses (or, leniently, warns about)
// unknown names; writing is atomic, and a saved project loads back exactly.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "jobs/pipe/pipe_job.h"
#include "jobs/project/unknown_names.h"

namespace polarform {

struct PipeProject {
  int degree = 3;
  std::vector<Eigen::Vector3d> points;  // mm
  std::vector<double> weights;          // one per point, > 0
  std::vector<double> knots;            // empty: clamped uniform on [0, 1]
  SpineClosure closure = SpineClosure::automatic;
  std::optional<double> radius, tolerance;  // mm
  FrameRule frame = FrameRule::rmf;

  bool operator==(const PipeProject&) const = default;
};

// The spine the project describes (its knots, or clamped uniform ones on [0, 1]).
NurbsCurve3d pipe_spine(const PipeProject& project);

// The job's options from the project (a radius it lacks stays 0; the command line may set it).
PipeJobOptions pipe_job_options(const PipeProject& project);

// Reads <polarform version="1"><pipe …/></polarform>, or a bare <pipe> root:
//   <pipe radius="mm" frame="rmf|frenet|fixed" tol="mm" degree="3" closed="auto|yes|no"
//         knots="u0,u1,…">
//     <point at="x,y,z" weight="1"/> …
//   </pipe>
// Knots, when given, number points + degree + 1, do not decrease, are clamped (degree + 1 equal
// at each end) and repeat at most `degree` times inside. Throws InputError "file:line: <pipe>
// attribute 'x': expected …" for bad values, and for unknown attributes or elements, which
// UnknownNames::warn turns into warnings.
PipeProject read_pipe_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                              UnknownNames policy = UnknownNames::refuse);
PipeProject parse_pipe_project(const std::string& text, const std::string& file,
                               std::vector<std::string>& warnings,
                               UnknownNames policy = UnknownNames::refuse);

// The project as XML (numbers in their shortest exact form) and saved atomically.
std::string pipe_project_xml(const PipeProject& project);
void write_pipe_project(const PipeProject& project, const std::filesystem::path& file);

}  // namespace polarform
