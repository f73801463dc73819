#!/usr/bin/env python3
"""Writes a finely tessellated torus as a Wavefront OBJ, for the mesh-loading benchmark
(bench/obj_load_bench.sh): shared vertices as real OBJ files have them, 2 * U * V triangles.

  gen_obj.py OUT.obj [--u 1000] [--v 500] [--attrs v|vn|vtvn] [--quads]

--attrs v: positions only ("f a b c"); vn: with vertex normals ("f a//a ..."); vtvn: normals and
texture coordinates, a seam where u and v wrap ("f a/t/a ..."), as exporters write them.
--quads: one 4-corner face per grid cell (split by the reader) instead of two triangles.
"""
import argparse
import math

ap = argparse.ArgumentParser()
ap.add_argument("out")
ap.add_argument("--u", type=int, default=1000)
ap.add_argument("--v", type=int, default=500)
ap.add_argument("--attrs", choices=["v", "vn", "vtvn"], default="vn")
ap.add_argument("--quads", action="store_true")
a = ap.parse_args()
U, V, R, r = a.u, a.v, 1.0, 0.4
with open(a.out, "w") as f:
    f.write(f"# torus {U}x{V}: {2 * U * V} triangles\no torus\n")
    for i in range(U):
        th = 2 * math.pi * i / U
        for j in range(V):
            ph = 2 * math.pi * j / V
            c = R + r * math.cos(ph)
            f.write(f"v {c * math.cos(th):.6f} {r * math.sin(ph):.6f} {c * math.sin(th):.6f}\n")
    if a.attrs != "v":
        for i in range(U):
            th = 2 * math.pi * i / U
            for j in range(V):
                ph = 2 * math.pi * j / V
                f.write(f"vn {math.cos(ph) * math.cos(th):.5f} {math.sin(ph):.5f} {math.cos(ph) * math.sin(th):.5f}\n")
    if a.attrs == "vtvn":  # (U+1) x (V+1): the seam gets its own coordinates
        for i in range(U + 1):
            for j in range(V + 1):
                f.write(f"vt {i / U:.6f} {j / V:.6f}\n")
    f.write("g surface\nusemtl default\n")
    for i in range(U):
        for j in range(V):
            q = [(i, j), ((i + 1) % U, j), ((i + 1) % U, (j + 1) % V), (i, (j + 1) % V)]
            t = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            def corner(k):
                p = q[k][0] * V + q[k][1] + 1
                if a.attrs == "v":
                    return str(p)
                if a.attrs == "vn":
                    return f"{p}//{p}"
                return f"{p}/{t[k][0] * (V + 1) + t[k][1] + 1}/{p}"
            c = [corner(k) for k in range(4)]
            if a.quads:
                f.write(f"f {c[0]} {c[3]} {c[2]} {c[1]}\n")
            else:
                f.write(f"f {c[0]} {c[3]} {c[2]}\nf {c[0]} {c[2]} {c[1]}\n")
