#include "ui/cli/commands.h"

namespace polarform::cli {

void register_commands(CLI::App& app) { (void)app; }

}  // namespace polarform::cli
