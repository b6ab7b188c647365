// polarform: command-line front end. Each subcommand lives in its own cmd_*.cpp and registers
// itself here; errors from bad input become one line on stderr and exit code 2, an inspected
// part out of tolerance exit code 3.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "polarform_version.h"
#include "src/error.h"
#include "ui/cli/commands.h"

namespace {

// "cam, study, …": the registered commands, for messages about a missing or unknown one.
std::string command_list(const CLI::App& app) {
  std::string list;
  for (const CLI::App* c : app.get_subcommands([](const CLI::App*) { return true; }))
    list += (list.empty() ? "" : ", ") + c->get_name();
  return list;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"polarform " POLARFORM_VERSION
               " - exact NURBS for rotational freeform profiles: cams, vessel heads, scans"};
  app.set_version_flag("--version", std::string("polarform ") + POLARFORM_VERSION);
  app.require_subcommand(1);
  polarform::cli::register_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // No command, or a word that is none: say which commands there are.
    if (app.get_subcommands().empty() && e.get_exit_code() != 0) {
      const std::string first = argc > 1 ? argv[1] : "";
      if (first.empty() || first[0] != '-') {
        std::cerr << "polarform: error: "
                  << (first.empty() ? "no command given" : "unknown command '" + first + "'")
                  << "; the commands are " << command_list(app)
                  << " (polarform --help describes them)\n";
        return 2;
      }
    }
    return app.exit(e) == 0 ? 0 : 2;
  } catch (const polarform::cli::OutOfTolerance& e) {
    std::cerr << "polarform: " << e.what() << "\n";
    return 3;
  } catch (const polarform::InputError& e) {
    std::cerr << "polarform: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "polarform: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
