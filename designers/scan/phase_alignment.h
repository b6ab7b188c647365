// Phase alignment of a scanned cam contour to its nominal design: the rotation δ about the cam
// centre (counter-clockwise), and optionally a mirror (the scan seen from the other face), that
// minimise the RMS radial difference R_scan(±ψ) − R_nom(ψ − δ) over a uniform grid of polar angles
// ψ: both radii tabulated once on the grid, every grid shift δ tried (a cyclic correlation), then
// golden-section refinement (Kiefer 1953) of the best bracket to 1e-9 rad.
#pragma once

#include <functional>

namespace polarform {

struct PhaseAlignment {
  double phase = 0.0;     // δ in [0, 2π): the (mirrored) scan is the nominal turned by δ
  bool mirrored = false;  // R_scan(−ψ) was aligned, i.e. the scan's y axis is flipped
  double rms = 0.0;       // RMS radial difference at δ, mm
};

// R_scan and R_nominal: radius at any polar angle (2π-periodic). samples >= 16 angles of ψ.
PhaseAlignment align_phase(const std::function<double(double)>& scan,
                           const std::function<double(double)>& nominal, bool allow_mirror,
                           int samples = 1440);

}  // namespace polarform
