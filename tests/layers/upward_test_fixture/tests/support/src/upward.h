// Kernel-level test support that includes a designer: the include-direction check must reject it.
#pragma once

#include "designers/cam/plate_cam.h"
#include "tests/support/src/sample_files.h"
