#include "ui/cli/commands.h"

namespace polarform::cli {

void register_commands(CLI::App& app) {
  add_cam_command(app);
  add_study_command(app);
  add_vessel_command(app);
  add_fit_command(app);
  add_viz_command(app);
  add_scan_cam_command(app);
  add_sweep_command(app);
  add_patch_command(app);
  add_pipe_command(app);
}

}  // namespace polarform::cli
