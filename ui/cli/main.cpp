// polarform: command-line front end. Each subcommand lives in its own cmd_*.cpp and registers
// itself here; errors from bad input become one line on stderr and exit code 2.
#include <CLI/CLI.hpp>
#include <iostream>

#include "polarform_version.h"
#include "src/error.h"
#include "ui/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"polarform " POLARFORM_VERSION
               " - exact NURBS for rotational freeform profiles: cams, vessel heads, scans"};
  app.set_version_flag("--version", std::string("polarform ") + POLARFORM_VERSION);
  app.require_subcommand(1);
  polarform::cli::register_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const polarform::InputError& e) {
    std::cerr << "polarform: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "polarform: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
