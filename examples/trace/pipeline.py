#!/usr/bin/env python3
"""pipeline.py: pipeline.c's geometry pipeline in Python with numpy, the way a student who
writes Python would do the assignment; without any of the catalogued mistakes.

    python3 pipeline.py SCENE TRACE

Needs numpy (pip install numpy, in a virtual environment) and close2gl_trace.py beside it.
Writes the 2D output in ortho2d 0 W 0 H (y up, as OpenGL).
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from close2gl_trace import TraceWriter, read_scene  # noqa: E402


def load_in(path):
    """The course's .in format: each triangle's v0, v1, v2 lines (x y z first) and its
    'face normal' line; the header before the first v0 is skipped."""
    corners, normals, triangle = [], [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) >= 4 and fields[0] in ("v0", "v1", "v2"):
                triangle.append([float(x) for x in fields[1:4]])
            elif fields[:2] == ["face", "normal"] and len(triangle) == 3:
                corners.append(triangle)
                normals.append([float(x) for x in fields[2:5]])
                triangle = []
    return np.array(corners, dtype=float), np.array(normals, dtype=float)


def load_obj(path):
    """Wavefront OBJ: v and f lines (v, v/vt, v//vn, v/vt/vn; negative indices), polygons as
    fans from their first corner."""
    vertices, corners = [], []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if fields[:1] == ["v"]:
                vertices.append([float(x) for x in fields[1:4]])
            elif fields[:1] == ["f"]:
                index = [int(c.split("/")[0]) for c in fields[1:]]
                index = [i - 1 if i > 0 else len(vertices) + i for i in index]
                for k in range(1, len(index) - 1):
                    corners.append([vertices[index[0]], vertices[index[k]], vertices[index[k + 1]]])
    return np.array(corners, dtype=float), np.zeros((len(corners), 3))


def bounding_sphere(corners):
    points = corners.reshape(-1, 3)
    lo, hi = points.min(axis=0), points.max(axis=0)
    return (lo + hi) * 0.5, 0.5 * math.sqrt(np.dot(hi - lo, hi - lo))


class Camera:
    def __init__(self, c, u, v, n, hfov, vfov, near, far):
        self.c, self.u, self.v, self.n = (np.array(x, dtype=float) for x in (c, u, v, n))
        self.hfov, self.vfov, self.near, self.far = hfov, vfov, near, far


def frame(corners, scene):
    """Looking along -z at the bounding box's centre, where the bounding sphere fits both fovs."""
    centre, r = bounding_sphere(corners)
    r = r if r > 0 else 1.0
    d = r / math.sin(min(scene.hfov, scene.vfov) * math.pi / 360)
    near = scene.near if scene.near is not None else 0.5 * (d - r)
    near = near if near > 0 else 0.01 * r
    far = scene.far if scene.far is not None else d + 2 * r
    if far <= near:
        if scene.near is not None:
            far = near + 2 * r
        else:
            near = 0.01 * far
    v, n = np.array([0.0, 1.0, 0.0]), np.array([0.0, 0.0, 1.0])
    return Camera(centre + np.array([0.0, 0.0, d]), np.cross(v, n), v, n,
                  scene.hfov, scene.vfov, near, far)


def normalize(a):
    return a * (1 / math.sqrt(np.dot(a, a)))


def apply_motion(cam, kind, axis, amount, lookat):
    u, v, n = cam.u, cam.v, cam.n
    angle = amount * math.pi / 180
    cs, sn = math.cos(angle), math.sin(angle)
    along = {"u": u, "v": v, "n": n}[axis]
    if kind == "move":
        cam.c = cam.c + along * amount
    elif kind == "rotate":
        if axis == "u":
            cam.v, cam.n = v * cs + n * sn, n * cs - v * sn
        elif axis == "v":
            cam.n, cam.u = n * cs + u * sn, u * cs - n * sn
        else:
            cam.u, cam.v = u * cs + v * sn, v * cs - u * sn
    else:
        cam.c = cam.c + along * amount
        cam.n = normalize(cam.c - lookat)
        if axis == "u":
            cam.u = normalize(np.cross(cam.v, cam.n))
            cam.v = np.cross(cam.n, cam.u)
        else:
            cam.v = normalize(np.cross(cam.n, cam.u))
            cam.u = np.cross(cam.v, cam.n)


def matrices(cam, o):
    c = cam.c
    M = np.array([[*cam.u, -np.dot(c, cam.u)], [*cam.v, -np.dot(c, cam.v)],
                  [*cam.n, -np.dot(c, cam.n)], [0, 0, 0, 1]], dtype=float)
    n, f = cam.near, cam.far
    t, r = n * math.tan(cam.vfov * 0.5 * (math.pi / 180)), n * math.tan(cam.hfov * 0.5 * (math.pi / 180))
    P = np.zeros((4, 4))
    P[0, 0], P[1, 1] = n / r, n / t
    P[2, 2], P[2, 3], P[3, 2] = -(f + n) / (f - n), -2 * f * n / (f - n), -1
    L, R, B, T = o
    V = np.zeros((4, 4))
    V[0, 0], V[0, 3], V[1, 1], V[1, 3] = (R - L) / 2, (R + L) / 2, (T - B) / 2, (T + B) / 2
    V[2, 2], V[2, 3], V[3, 3] = 0.5, 0.5, 1
    return M, P, V


def distance(p, i):
    """Signed distance to plane i of x >= -w, x <= w, y >= -w, ... z <= w: inside >= 0."""
    return p[3] + (-1 if i % 2 else 1) * p[i // 2]


def inside(p, i):
    return distance(p, i) >= 0 and (i != 4 or p[3] > 0)


def clip_polygon(poly):
    """Sutherland-Hodgman against the six planes; the corners left and whether any plane cut."""
    cut = False
    for i in range(6):
        if len(poly) < 3:
            break
        if all(inside(p, i) for p in poly):
            continue
        cut = True
        if i == 4 and any(p[3] <= 0 and distance(p, 4) >= 0 for p in poly):
            return [], True
        before, poly = poly, []
        for j, a in enumerate(before):
            b = before[(j + 1) % len(before)]
            ia, ib = inside(a, i), inside(b, i)
            if ia:
                poly.append(a)
            if ia and not ib and distance(a, i) > 0:
                poly.append(crossing(a, b, i))
            if not ia and ib and distance(b, i) > 0:
                poly.append(crossing(b, a, i))
    return poly, cut


def crossing(a, b, i):
    da, db = distance(a, i), distance(b, i)
    return a + (da / (da - db)) * (b - a)


def culled(culling, xyz):
    if culling == "off":
        return False
    area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(xyz, xyz[1:] + xyz[:1]))
    return area <= 0 if culling == "ccw" else area >= 0


def main():
    if len(sys.argv) != 3:
        sys.exit(f"usage: {sys.argv[0]} SCENE TRACE")
    scene = read_scene(sys.argv[1])
    load = load_obj if scene.model.lower().endswith(".obj") else load_in
    corners, _ = load(scene.model)
    if scene.framed:
        cam = frame(corners, scene)
    else:
        cam = Camera(scene.position, scene.u, scene.v, scene.n, scene.hfov, scene.vfov,
                     scene.near, scene.far)
    lookat = np.array(scene.lookat, dtype=float) if scene.lookat else bounding_sphere(corners)[0]
    for kind, axis, amount in scene.motions:
        apply_motion(cam, kind, axis, amount, lookat)
    width, height = scene.window
    o = (0.0, float(width), 0.0, float(height))
    M, P, V = matrices(cam, o)
    PM = P @ M
    with open(sys.argv[2], "w") as f:
        t = TraceWriter(f)
        t.model(os.path.basename(scene.model))
        t.triangles(len(corners))
        t.window(width, height)
        t.ortho2d(*o)
        t.camera(cam.c, cam.u, cam.v, cam.n, cam.hfov, cam.vfov, cam.near, cam.far)
        t.culling(scene.culling)
        t.clipping(scene.clipping)
        t.mode(scene.mode)
        for which, m in (("M", M), ("P", P), ("V", V)):
            t.matrix(which, m)
        clip = np.einsum("ij,tkj->tki", PM, np.concatenate(
            [corners, np.ones((len(corners), 3, 1))], axis=2))
        for i, poly in enumerate(clip):
            t.clip(i, poly)
            draw(t, i, list(poly), scene, V)
        t.end()


def draw(t, i, poly, scene, V):
    """Clipping, division, viewport, culling, and the tri or poly line of mesh triangle i."""
    cut = False
    if scene.clipping == "simple":
        if any(not (abs(p[0]) <= p[3] and abs(p[1]) <= p[3] and abs(p[2]) <= p[3] and p[3] > 0)
               for p in poly):
            return
    elif scene.clipping == "full":
        poly, cut = clip_polygon(poly)
        if len(poly) < 3:
            return
    elif any(p[3] == 0 for p in poly):
        return
    xyz = []
    for p in poly:
        ndc = np.array([p[0] / p[3], p[1] / p[3], p[2] / p[3], 1.0])
        q = V @ ndc
        xyz.append((q[0], q[1], ndc[2]))
    if culled(scene.culling, xyz):
        return
    if cut:
        t.poly(i, xyz)
    else:
        t.tri(i, xyz)


if __name__ == "__main__":
    main()
