#!/usr/bin/env python3
"""Generates the OBJ models used by ../features/mesh.sc (pure standard library, deterministic).

Run from anywhere:  python3 scenes/meshes/generate.py
Every model here is made by this script; nothing is downloaded or copied from elsewhere.

blob.obj: an icosahedron subdivided four times (5,120 triangles) onto the sphere of radius 0.5,
each vertex pushed out along its direction by a sum of smooth bumps. Smooth vertex normals
(area-weighted face normals) and spherical texture coordinates (u around the y axis, v up, as
OBJ exporters write them), with the corners of triangles that straddle the u seam moved to u > 1
so that no triangle's texture runs backwards across the whole image.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def icosphere(levels):
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [normalize(v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        midpoint = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                va, vb = verts[a], verts[b]
                verts.append(normalize(tuple((x + y) / 2 for x, y in zip(va, vb))))
                midpoint[key] = len(verts) - 1
            return midpoint[key]

        new_faces = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = new_faces
    return verts, faces


def normalize(v):
    n = math.sqrt(sum(x * x for x in v))
    return tuple(x / n for x in v)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def bump(d):
    x, y, z = d
    return 1 + 0.18 * math.sin(5 * x) * math.sin(4 * y + 1) * math.sin(5 * z + 0.5) + 0.08 * math.cos(9 * y)


def write_blob(path):
    dirs, faces = icosphere(4)
    pos = [tuple(0.5 * bump(d) * c for c in d) for d in dirs]
    normals = [(0.0, 0.0, 0.0)] * len(pos)
    for a, b, c in faces:
        n = cross(sub(pos[b], pos[a]), sub(pos[c], pos[a]))  # length = twice the area
        for i in (a, b, c):
            normals[i] = tuple(x + y for x, y in zip(normals[i], n))
    normals = [normalize(n) for n in normals]
    uvs = []  # one per vertex, then the seam copies
    for x, y, z in dirs:
        uvs.append((0.5 - math.atan2(z, x) / (2 * math.pi), 0.5 + math.asin(max(-1.0, min(1.0, y))) / math.pi))
    face_uvs = []
    for face in faces:
        corner = [i + 1 for i in face]
        if max(uvs[i][0] for i in face) - min(uvs[i][0] for i in face) > 0.5:
            for k, i in enumerate(face):
                if uvs[i][0] < 0.5:
                    uvs.append((uvs[i][0] + 1, uvs[i][1]))
                    corner[k] = len(uvs)
        face_uvs.append(corner)
    with open(path, "w") as f:
        f.write("# blob.obj -- written by generate.py: a displaced icosphere, %d triangles\n" % len(faces))
        for p in pos:
            f.write("v %.5f %.5f %.5f\n" % p)
        for n in normals:
            f.write("vn %.4f %.4f %.4f\n" % n)
        for u, v in uvs:
            f.write("vt %.4f %.4f\n" % (u, v))
        for (a, b, c), (ta, tb, tc) in zip(faces, face_uvs):
            f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a + 1, ta, a + 1, b + 1, tb, b + 1, c + 1, tc, c + 1))


if __name__ == "__main__":
    write_blob(os.path.join(HERE, "blob.obj"))
