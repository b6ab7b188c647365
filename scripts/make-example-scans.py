#!/usr/bin/env python3
"""Regenerates examples/scans: synthetic scans with known answers (Python 3 standard library only).

Every file is deterministic (random.Random with a fixed seed per file) and states its shape, its
placement and its noise in its header comment. Run from the repository root:

    python3 scripts/make-example-scans.py [OUTPUT_DIR]      (default: examples/scans)
"""
import math
import os
import random
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join("examples", "scans")


def rotation(axis, angle):
    """Rodrigues' rotation matrix about a unit axis."""
    n = math.sqrt(sum(a * a for a in axis))
    x, y, z = (a / n for a in axis)
    c, s, t = math.cos(angle), math.sin(angle), 1 - math.cos(angle)
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def place(p, rot, shift):
    return [sum(rot[r][c] * p[c] for c in range(3)) + shift[r] for r in range(3)]


def write(name, header, rows, fmt="{:.6f} {:.6f} {:.6f}"):
    path = os.path.join(OUT, name)
    with open(path, "w", encoding="ascii", newline="\n") as f:
        for line in header:
            f.write("# " + line + "\n")
        for row in rows:
            f.write(fmt.format(*row) + "\n")
    print(f"{path}: {len(rows)} rows, {os.path.getsize(path)} bytes")


def sphere_like(rng):
    """rho(phi, theta) = 30 (1 + 0.1 sin^3 phi cos 3 theta) / sqrt(1 + 0.3 cos^2 phi) mm."""
    rot, shift, sigma = rotation((1, 1, 0), math.radians(25)), (10, -5, 20), 0.02
    rows = []
    for _ in range(3000):
        phi, theta = math.acos(rng.uniform(-1, 1)), rng.uniform(0, 2 * math.pi)
        s, c = math.sin(phi), math.cos(phi)
        rho = 30 * (1 + 0.1 * s ** 3 * math.cos(3 * theta)) / math.sqrt(1 + 0.3 * c * c)
        p = [rho * s * math.cos(theta), rho * s * math.sin(theta), rho * c]
        rows.append([v + rng.gauss(0, sigma) for v in place(p, rot, shift)])
    write("sphere_like.xyz", [
        "polarform example scan (scripts/make-example-scans.py, seed 1): a sphere-like body,",
        "rho(phi, theta) = 30 (1 + 0.1 sin^3 phi cos 3 theta) / sqrt(1 + 0.3 cos^2 phi) mm,",
        "area-uniform in (phi, theta), rotated 25 deg about (1, 1, 0) and moved by (10, -5, 20) mm;",
        "noise N(0, 0.02^2) mm per coordinate. x y z in mm."], rows)


def vase(rng):
    """r(z, theta) = 24 - 5 sin(pi z / 80) + 0.8 cos 2 theta z / 80 mm, z in [0, 80]."""
    rot, shift, sigma = rotation((0, 1, 0), math.radians(90)), (0, 0, 5), 0.02
    rows = []
    for _ in range(3000):
        z, theta = rng.uniform(0, 80), rng.uniform(0, 2 * math.pi)
        r = 24 - 5 * math.sin(math.pi * z / 80) + 0.8 * math.cos(2 * theta) * z / 80
        p = [r * math.cos(theta), r * math.sin(theta), z]
        rows.append([v + rng.gauss(0, sigma) for v in place(p, rot, shift)])
    write("vase.xyz", [
        "polarform example scan (scripts/make-example-scans.py, seed 2): a waisted vase,",
        "r(z, theta) = 24 - 5 sin(pi z / 80) + 0.8 cos(2 theta) z / 80 mm, z in [0, 80] mm,",
        "uniform in (z, theta), axis turned 90 deg about y (to +x) and moved by (0, 0, 5) mm;",
        "noise N(0, 0.02^2) mm per coordinate. x y z in mm."], rows)


def lobed_profile(rng):
    """A planar profile r(theta) = 25 + 3 cos 3theta + 1.5 sin 5theta mm about (4, -3)."""
    rot, shift, sigma = rotation((1, 0, 0), math.radians(20)), (0, 10, 30), 0.01
    rows = []
    for _ in range(1500):
        theta = rng.uniform(0, 2 * math.pi)
        r = 25 + 3 * math.cos(3 * theta) + 1.5 * math.sin(5 * theta)
        p = [4 + r * math.cos(theta), -3 + r * math.sin(theta), 0.0]
        rows.append([v + rng.gauss(0, sigma) for v in place(p, rot, shift)])
    write("lobed_profile.xyz", [
        "polarform example scan (scripts/make-example-scans.py, seed 5): a planar profile,",
        "r(theta) = 25 + 3 cos(3 theta) + 1.5 sin(5 theta) mm about the centre (4, -3) in the plane",
        "z = 0, uniform in theta, turned 20 deg about x and moved by (0, 10, 30) mm;",
        "noise N(0, 0.01^2) mm per coordinate. x y z in mm."], rows)


def roller_cam_lift(theta):
    """s, ds/dtheta of examples/cams/roller.xml: dwell 0-90, cycloidal rise of 20 mm 90-180,
    dwell 180-240, 4-5-6-7 return 240-360 (Norton, Cam Design Handbook, ch. 3)."""
    d = math.degrees(theta) % 360
    if d < 90:
        return 0.0, 0.0
    if d < 180:
        b, x = math.radians(90), (d - 90) / 90
        return 20 * (x - math.sin(2 * math.pi * x) / (2 * math.pi)), 20 / b * (1 - math.cos(2 * math.pi * x))
    if d < 240:
        return 20.0, 0.0
    b, x = math.radians(120), (d - 240) / 120
    p = 35 * x ** 4 - 84 * x ** 5 + 70 * x ** 6 - 20 * x ** 7
    dp = 140 * x ** 3 - 420 * x ** 4 + 420 * x ** 5 - 140 * x ** 6
    return 20 * (1 - p), -20 / b * dp


def roller_cam_contour(theta, offset):
    """Contour point of examples/cams/roller.xml at cam angle theta, moved `offset` along the
    contour normal: in the follower frame the pitch point is (0, y0 + s) with the outward pitch
    normal (-s', y0 + s)/|.|; the cam frame sees both turned by -theta (plate_cam.h)."""
    rb, rr = 40.0, 10.0
    lift, dlift = roller_cam_lift(theta)
    mx, my = -dlift, rb + rr + lift
    norm = math.hypot(mx, my)
    d = offset - rr
    fx, fy = d * mx / norm, rb + rr + lift + d * my / norm
    ct, st = math.cos(theta), math.sin(theta)
    return ct * fx + st * fy, -st * fx + ct * fy


def cam_profile(rng):
    """A 2D profile scan of examples/cams/roller.xml (Rb 40, radial roller Rr 10, ccw)."""
    phase, centre, sigma = math.radians(30), (12.5, -7.25), 0.005
    c, s = math.cos(phase), math.sin(phase)
    rows = []

    def put(x, y):
        rows.append([centre[0] + c * x - s * y, centre[1] + s * x + c * y, 0.0])

    for _ in range(3600):
        put(*roller_cam_contour(rng.uniform(0, 2 * math.pi), rng.gauss(0, sigma)))
    for _ in range(400):
        a, r = rng.uniform(0, 2 * math.pi), 8.0 + rng.gauss(0, sigma)
        put(r * math.cos(a), r * math.sin(a))
    write("cam_profile.xyz", [
        "polarform example scan (scripts/make-example-scans.py, seed 3): a 2D profile scan of",
        "the plate cam examples/cams/roller.xml (base radius 40 mm, radial roller 10 mm, ccw;",
        "cycloidal rise of 20 mm over 90-180 deg, 4-5-6-7 return over 240-360 deg): 3600 contour",
        "points at uniformly random cam angles, moved along the contour normal by N(0, 0.005^2) mm,",
        "and 400 points of an 8 mm bore; the cam turned 30 deg ccw with its centre at (12.5, -7.25).",
        "x y z in mm (z = 0)."], rows)


def cam_plate(rng):
    """A 3D scan of examples/cams/roller.xml as a 10 mm plate with its 8 mm bore."""
    rot, shift, sigma, half = rotation((1, -2, 0.5), math.radians(35)), (120, 40, -15), 0.01, 5.0
    pts = []
    for face in (-half, half):  # along rays between the bore and the contour (not area-uniform)
        for _ in range(1200):
            x, y = roller_cam_contour(rng.uniform(0, 2 * math.pi), 0.0)
            r = math.hypot(x, y)
            t = (8.0 + rng.random() * (r - 8.0)) / r
            pts.append([t * x, t * y, face])
    for _ in range(2400):
        x, y = roller_cam_contour(rng.uniform(0, 2 * math.pi), 0.0)
        pts.append([x, y, rng.uniform(-half, half)])
    for _ in range(300):
        a = rng.uniform(0, 2 * math.pi)
        pts.append([8 * math.cos(a), 8 * math.sin(a), rng.uniform(-half, half)])
    rows = [[v + rng.gauss(0, sigma) for v in place(p, rot, shift)] for p in pts]
    write("cam_plate.xyz", [
        "polarform example scan (scripts/make-example-scans.py, seed 4): a 3D scan of the plate cam",
        "examples/cams/roller.xml made as a 10 mm plate with an 8 mm bore, in its own cam frame",
        "(z = -5 .. 5), then turned 35 deg about (1, -2, 0.5) and moved by (120, 40, -15) mm:",
        "1200 points on each face, 2400 on the side wall, 300 on the bore wall; noise N(0, 0.01^2) mm",
        "per coordinate. x y z in mm."], rows)


def sphere_grid():
    """A field on a spherical set-up: p = 100 + 20 cos phi + 6 sin^2 phi cos 2 theta (kPa)."""
    rows = []
    for i in range(19):
        for j in range(36):
            phi, theta = math.radians(10 * i), math.radians(10 * j)
            p = 100 + 20 * math.cos(phi) + 6 * math.sin(phi) ** 2 * math.cos(2 * theta)
            rows.append([p, 10 * i, 10 * j])
    path_rows = ["{:.6f},{:g},{:g}".format(*r) for r in rows]
    path = os.path.join(OUT, "sphere_grid.csv")
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write("# polarform example grid (scripts/make-example-scans.py): pressure on a sphere,\n")
        f.write("# p = 100 + 20 cos(phi) + 6 sin^2(phi) cos(2 theta) kPa on a 10 deg grid (exact).\n")
        f.write("pressure_kPa,phi_deg,theta_deg\n")
        f.write("\n".join(path_rows) + "\n")
    print(f"{path}: {len(rows)} rows, {os.path.getsize(path)} bytes")


def main():
    os.makedirs(OUT, exist_ok=True)
    sphere_like(random.Random(1))
    vase(random.Random(2))
    cam_profile(random.Random(3))
    cam_plate(random.Random(4))
    lobed_profile(random.Random(5))
    sphere_grid()


if __name__ == "__main__":
    main()
