// polarform-studio: the desktop app. Parses the command line and runs the app shell; a failure
// to start (no display, no OpenGL 3.3) is one line on stderr and exit code 1.
#include <malloc.h>

#include <exception>
#include <iostream>

#include "ui/studio/app.h"
#include "ui/studio/studio_options.h"

int main(int argc, char** argv) {
  // Every frame uploads its vertex buffers anew (the OpenGL backend's glBufferData) and rebuilds
  // the plots' samples: with glibc's default thresholds those blocks come from fresh pages each
  // time, and the page faults cost a software renderer more than the drawing. Keep freed memory
  // in the heap instead (mmap only above 32 MiB, trim above 256 MiB).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
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
