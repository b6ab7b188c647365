#!/usr/bin/env python3
"""Independent read-back of a DXF file with ezdxf, for the exchange tests (test_export).

Usage: dxf_inspect.py SAMPLES FILE.dxf [FILE.dxf ...]
Prints a JSON list with one object per file: the DXF version and $INSUNITS, ezdxf's audit errors
and fixes, and for every entity of the model space its type, layer and data; a SPLINE also carries its flags,
degree, knots, weights, control points, normal and SAMPLES points that ezdxf itself evaluates at
equally spaced parameters of its domain [knots[degree], knots[count]] (reported as "params").
Exit status 3 (message on stderr) when ezdxf cannot be imported, so the caller can skip.
"""
import json
import sys

try:
    import ezdxf
except ImportError as error:  # the caller turns this into a skipped test
    print(f"ezdxf is not importable by {sys.executable}: {error}", file=sys.stderr)
    sys.exit(3)


def spline_data(entity, samples):
    tool = entity.construction_tool()  # ezdxf.math.BSpline, rational when weights are present
    knots = list(entity.knots)
    degree = entity.dxf.degree
    count = len(entity.control_points)
    lo, hi = knots[degree], knots[count]
    params = [lo + (hi - lo) * i / (samples - 1) for i in range(samples)]
    # ezdxf rescales a knot vector that does not start at 0 to [0, 1]: evaluate at the matching
    # parameters of its own knots.
    tk = tool.knots()
    tlo, thi = tk[degree], tk[count]
    tool_params = [tlo + (thi - tlo) * i / (samples - 1) for i in range(samples)]
    return {
        "flags": entity.dxf.flags,
        "degree": degree,
        "knots": knots,
        "weights": list(entity.weights),
        "control_points": [list(p) for p in entity.control_points],
        "normal": list(entity.dxf.extrusion) if entity.dxf.hasattr("extrusion") else None,
        "params": params,
        "points": [list(tool.point(t)) for t in tool_params],
    }


def inspect(path, samples):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    out = {
        "ezdxf": ezdxf.__version__,
        "dxfversion": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS"),
        "audit_errors": [str(e.message) for e in auditor.errors],
        "audit_fixes": [str(e.message) for e in auditor.fixes],
        "layers": sorted(layer.dxf.name for layer in doc.layers),
        "entities": [],
    }
    for entity in doc.modelspace():
        item = {"type": entity.dxftype(), "layer": entity.dxf.layer}
        if item["type"] == "SPLINE":
            item.update(spline_data(entity, samples))
        elif item["type"] == "LINE":
            item.update(start=list(entity.dxf.start), end=list(entity.dxf.end))
        elif item["type"] == "CIRCLE":
            item.update(center=list(entity.dxf.center), radius=entity.dxf.radius)
        elif item["type"] == "LWPOLYLINE":
            item.update(points=[list(p[:2]) for p in entity.get_points()], closed=entity.closed)
        out["entities"].append(item)
    return out


def main():
    samples = int(sys.argv[1])
    json.dump([inspect(path, samples) for path in sys.argv[2:]], sys.stdout)


if __name__ == "__main__":
    main()
