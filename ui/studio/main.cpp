// polarform-studio: the desktop app. Parses the command line and runs the app shell; a failure
// to start (no display, no OpenGL 3.3) is one line on stderr and exit code 1.
#include <exception>
#include <iostream>

#include "ui/studio/app.h"
#include "ui/studio/studio_options.h"

int main(int argc, char** argv) {
  int exit_code = 0;
  const auto options = polarform::studio::parse_options(argc, argv, exit_code);
  if (!options) return exit_code;
  try {
    polarform::studio::App app(*options);
    return app.run();
  } catch (const std::exception& e) {
    std::cerr << "polarform-studio: " << e.what() << "\n";
    return 1;
  }
}
