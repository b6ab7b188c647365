// A kernel test that uses the designers' test support: the include-direction check must reject it.
#include "src/nurbs/bspline.h"
#include "tests/src/nurbs/kernel_test_support.h"
#include "tests/support/designers/synthetic_scans.h"
