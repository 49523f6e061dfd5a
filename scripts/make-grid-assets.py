#!/usr/bin/env python3
"""Makes assets/grids/: tetrahedral grids of meshes the project bundles, by Debian's tetgen, with a
scalar synthesized per point. Run from the repository root (needs the `tetgen` package):

    python3 scripts/make-grid-assets.py

For each mesh: its OBJ written as OFF, `tetgen -p` (a constrained Delaunay tetrahedralization of
the surface, no quality refinement: cells graded from the surface's small triangles to large ones
inside, as real finite-element grids are), and the .node rewritten with one point attribute, the
scalar: a smooth field over the mesh's box, s = 0.5 + 0.5 sin(3 pi u) cos(2 pi v) (w + 0.5) / 1.5
with (u, v, w) the point's position in the box, 0 to 1 on each axis."""

import math
import os
import shutil
import subprocess
import sys
import tempfile

MESHES = {"bunny": "assets/models/bunny-lowres.obj"}


def read_obj(path):
    vertices, faces = [], []
    for line in open(path):
        parts = line.split()
        if parts and parts[0] == "v":
            vertices.append(tuple(map(float, parts[1:4])))
        elif parts and parts[0] == "f":
            faces.append([int(p.split("/")[0]) - 1 for p in parts[1:]])
    return vertices, faces


def main():
    if shutil.which("tetgen") is None:
        sys.exit("make-grid-assets: tetgen is not installed (apt-get install tetgen)")
    os.makedirs("assets/grids", exist_ok=True)
    for name, source in MESHES.items():
        vertices, faces = read_obj(source)
        with tempfile.TemporaryDirectory() as work:
            off = os.path.join(work, name + ".off")
            with open(off, "w") as out:
                out.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
                for v in vertices:
                    out.write("%r %r %r\n" % v)
                for f in faces:
                    out.write("%d %s\n" % (len(f), " ".join(map(str, f))))
            subprocess.run(["tetgen", "-pQ", off], check=True)
            stem = os.path.join(work, name + ".1")
            points = []
            with open(stem + ".node") as node:
                rows = [line.split() for line in node if line.strip() and not line.startswith("#")]
            count = int(rows[0][0])
            for row in rows[1:1 + count]:
                points.append((int(row[0]), float(row[1]), float(row[2]), float(row[3])))
            low = [min(p[k] for p in points) for k in (1, 2, 3)]
            high = [max(p[k] for p in points) for k in (1, 2, 3)]
            with open("assets/grids/%s.node" % name, "w") as out:
                out.write("# %s by tetgen -p, scalar synthesized (scripts/make-grid-assets.py)\n" % source)
                out.write("%d 3 1 0\n" % count)
                for index, *xyz in points:
                    u, v, w = ((xyz[k] - low[k]) / (high[k] - low[k]) for k in range(3))
                    s = 0.5 + 0.5 * math.sin(3 * math.pi * u) * math.cos(2 * math.pi * v) * (w + 0.5) / 1.5
                    out.write("%d %r %r %r %.6f\n" % (index, *xyz, s))
            shutil.copy(stem + ".ele", "assets/grids/%s.ele" % name)


if __name__ == "__main__":
    main()
