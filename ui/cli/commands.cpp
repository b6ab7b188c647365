#include "ui/cli/commands.h"

namespace polarform::cli {

void register_commands(CLI::App& app) {
  add_cam_command(app);
  add_study_command(app);
  add_vessel_command(app);
}

}  // namespace polarform::cli
