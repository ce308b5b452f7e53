"""py_fullclip.py: the assignment in Python, standard library only, double: matrices as lists of
rows, full clipping (Sutherland-Hodgman against the six planes in clip coordinates: a cut triangle
is drawn as the polygon left), the 2D output in the assignment template's system
(gluOrtho2D(0, 1, 0, 1)), culling by the winding on screen.

    python3 py_fullclip.py SCENE TRACE

Lines ending in "[trace]" were added only to write the trace.

expect cube_front: agree
expect knot_through: agree
expect knot_cw: agree
expect inside_cube: agree
expect-grade cube: 200
"""
import math
import sys

from close2gl_trace import TraceWriter, read_scene  # [trace] (read_scene: the scene's reader)
from model import load_model


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    length = math.sqrt(dot(a, a))
    return [x / length for x in a]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


class Camera:
    def __init__(self, c, u, v, n):
        self.c, self.u, self.v, self.n = list(c), list(u), list(v), list(n)

    def turn(self, a, b, degrees):
        t = math.radians(degrees)
        x, y = getattr(self, a), getattr(self, b)
        setattr(self, a, [math.cos(t) * p + math.sin(t) * q for p, q in zip(x, y)])
        setattr(self, b, [math.cos(t) * q - math.sin(t) * p for p, q in zip(x, y)])

    def apply(self, kind, axis, amount, target):
        if kind == "rotate":
            self.turn(*{"u": ("v", "n"), "v": ("n", "u"), "n": ("u", "v")}[axis], amount)
            return
        self.c = [p + amount * q for p, q in zip(self.c, getattr(self, axis))]
        if kind == "orbit":
            self.n = unit(sub(self.c, target))
            if axis == "u":
                self.u = unit(cross(self.v, self.n))
                self.v = cross(self.n, self.u)
            else:
                self.v = unit(cross(self.n, self.u))
                self.u = cross(self.v, self.n)

    def modelview(self):
        return [self.u + [-dot(self.u, self.c)], self.v + [-dot(self.v, self.c)],
                self.n + [-dot(self.n, self.c)], [0, 0, 0, 1]]


def clip_polygon(poly):
    """Sutherland-Hodgman against x, y, z >= -w and <= w."""
    for axis in range(3):
        for sign in (1, -1):
            def dist(p):
                return p[3] + sign * p[axis]
            out = []
            for i, a in enumerate(poly):
                b = poly[(i + 1) % len(poly)]
                if dist(a) >= 0:
                    out.append(a)
                if (dist(a) >= 0) != (dist(b) >= 0):
                    t = dist(a) / (dist(a) - dist(b))
                    out.append([p + t * (q - p) for p, q in zip(a, b)])
            poly = out
            if len(poly) < 3:
                return []
    return poly


def main(scene_path, trace_path):
    scene = read_scene(scene_path)
    triangles = load_model(scene.model)
    corners = [p for t in triangles for p in t]
    lo = [min(p[k] for p in corners) for k in range(3)]
    hi = [max(p[k] for p in corners) for k in range(3)]
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    radius = math.dist(lo, hi) / 2
    if scene.framed:
        d = radius / math.sin(math.radians(min(scene.hfov, scene.vfov)) / 2)
        cam = Camera([centre[0], centre[1], centre[2] + d], [1, 0, 0], [0, 1, 0], [0, 0, 1])
        near = scene.near if scene.near is not None else (d - radius) / 2
        far = scene.far if scene.far is not None else d + 2 * radius
    else:
        cam = Camera(scene.position, scene.u, scene.v, scene.n)
        near, far = scene.near, scene.far
    for kind, axis, amount in scene.motions:
        cam.apply(kind, axis, amount, scene.lookat or centre)

    M = cam.modelview()
    right = near * math.tan(math.radians(scene.hfov) / 2)
    top = near * math.tan(math.radians(scene.vfov) / 2)
    P = [[near / right, 0, 0, 0], [0, near / top, 0, 0],
         [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)], [0, 0, -1, 0]]
    PM = matmul(P, M)

    with open(trace_path, "w") as f:  # [trace]
        trace = TraceWriter(f)  # [trace]
        trace.window(*scene.window)  # [trace]
        trace.ortho2d(0, 1, 0, 1)  # [trace]
        trace.camera(cam.c, cam.u, cam.v, cam.n, scene.hfov, scene.vfov, near, far)  # [trace]
        trace.culling(scene.culling)  # [trace]
        trace.clipping("full")  # [trace]
        trace.matrix("M", M)  # [trace]
        trace.matrix("P", P)  # [trace]
        trace.matrix("V", [[0.5, 0, 0, 0.5], [0, 0.5, 0, 0.5], [0, 0, 0.5, 0.5], [0, 0, 0, 1]])  # [trace]
        trace.mode(scene.mode)  # [trace]
        for t, tri in enumerate(triangles):
            clip = [[dot(row[:3], p) + row[3] for row in PM] for p in tri]
            poly = clip_polygon(clip)
            xy = [((p[0] / p[3] + 1) / 2, (p[1] / p[3] + 1) / 2) for p in poly]
            area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(xy, xy[1:] + xy[:1]))
            if not poly or (scene.culling == "ccw" and area <= 0) or (scene.culling == "cw" and area >= 0):
                xy = None
            trace.triangle(t, clip, xy)  # [trace]
        trace.end()  # [trace]


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
