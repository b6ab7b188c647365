#!/usr/bin/env python3
"""Writes a synthetic scan of a sphere-like part as an xyz point cloud, for the studio's
screenshots and frame-time measurements: a bumpy egg (three lobes around the axis, flattened
top) of radius ~50 mm, open at the bottom like a real scan, tilted and moved away from the
origin, with 0.02 mm Gaussian noise. Deterministic (fixed seed).

usage: synthetic_scan.py OUT.xyz [POINTS]   (default 20000 points)
"""
import math
import random
import sys


def main() -> int:
    if len(sys.argv) not in (2, 3):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    out, count = sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 20000
    rng = random.Random(20021)
    tilt = math.radians(20.0)
    ct, st = math.cos(tilt), math.sin(tilt)
    lines = []
    for _ in range(count):
        # Directions uniform on the sphere, polar angle up to 150° (the bottom is not scanned).
        z = rng.uniform(math.cos(math.radians(150.0)), 1.0)
        phi = math.acos(z)
        theta = rng.uniform(0.0, 2.0 * math.pi)
        lobes = 0.08 * math.cos(3.0 * theta) * math.sin(phi) ** 2
        r = 50.0 * (1.0 + lobes - 0.06 * math.cos(phi) ** 2)
        r += rng.gauss(0.0, 0.02)
        rho = r * math.sin(phi)
        x, y, zz = rho * math.cos(theta), rho * math.sin(theta), r * math.cos(phi)
        # Tilt about x and move away from the origin, as a scanner's coordinates would be.
        y, zz = ct * y - st * zz, st * y + ct * zz
        lines.append(f"{x + 120.0:.5f} {y - 35.0:.5f} {zz + 210.0:.5f}\n")
    with open(out, "w", encoding="ascii") as f:
        f.writelines(lines)
    return 0


if __name__ == "__main__":
    sys.exit(main())
