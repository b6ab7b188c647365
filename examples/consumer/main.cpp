// The consumer example: reads a cam project with polarform's jobs API, runs the cam job and prints
// the polarform version it was built against and the profile conversion's tolerance, measured
// maximum radial error and control points. It is built against an installed polarform
// (find_package), as a program outside the tree would be.
//   polarform_consumer <cam project.xml>     exit 0, 2 on bad input, 1 on any other failure
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "jobs/cam/cam_job.h"
#include "jobs/project/cam_project.h"
#include "polarform_version.h"
#include "src/error.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: polarform_consumer <cam project.xml>\n";
    return 2;
  }
  try {
    std::vector<std::string> warnings;
    const polarform::CamProject project = polarform::read_cam_project(argv[1], warnings);
    for (const std::string& warning : warnings) std::cerr << "warning: " << warning << '\n';
    const polarform::CamJobResult result = polarform::run_cam_job(project);
    const polarform::PolarConversion& conversion = result.conversion.conversion;
    std::cout << "polarform " << POLARFORM_VERSION << '\n'
              << "tolerance_mm " << conversion.tolerance << '\n'
              << "max_radial_error_mm " << conversion.max_radial_error << '\n'
              << "control_points " << result.conversion.control_points() << '\n'
              << "degree " << result.conversion.degree() << '\n';
  } catch (const polarform::InputError& e) {
    std::cerr << "polarform_consumer: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "polarform_consumer: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
