// A designer test that uses only what it may: its layer and below, their test support, its own
// layer's tests. The include-direction check must accept it.
#include "designers/cam/plate_cam.h"
#include "src/nurbs/bspline.h"
#include "tests/designers/cam/cam_test_support.h"
#include "tests/support/designers/synthetic_scans.h"
#include "tests/support/src/sample_files.h"
