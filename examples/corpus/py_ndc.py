"""py_ndc.py: a Python program that hands NDC to the GPU (PyOpenGL's habit: the GPU does the
viewport and cuts x and y at the window's edge), so it clips only against the near and far
planes (a triangle with a corner outside them is dropped, the rest sent whole) and culls by the
winding of NDC x, y. Standard library only; matrices are flat tuples, row by row.

    python3 py_ndc.py SCENE TRACE [-DIGNORES_FRONT_FACE] [-DALWAYS_CULLS] [-DDRAWS_NOTHING]

Variants: -DIGNORES_FRONT_FACE always takes counter-clockwise as front, whatever the scene's
culling says; -DALWAYS_CULLS culls back faces (counter-clockwise front) even with culling off,
as a program that calls glEnable(GL_CULL_FACE) once and forgets it; it writes the scene's culling.
-DDRAWS_NOTHING computes every triangle's clip coordinates and draws none, as a program whose
draw call was left commented out.

Lines ending in "[trace]" were added only to write the trace.

expect cube_front: agree
expect knot_through: agree
expect knot_cw: agree
expect inside_cube: agree
expect knot_cw -DIGNORES_FRONT_FACE: differs stage=culling names=culling_inverted,culling_ignores_front_face
expect knot_turned -DIGNORES_FRONT_FACE: agree
expect inside_cube -DALWAYS_CULLS: differs stage=culling unexplained
expect cube_front -DALWAYS_CULLS: agree
expect cube_front -DDRAWS_NOTHING: differs stage=culling unexplained
expect inside_cube -DDRAWS_NOTHING: differs stage=culling unexplained
expect-grade cube: 200
expect-grade cube -DIGNORES_FRONT_FACE: culling=16 synchronized=23
expect-grade cube -DALWAYS_CULLS: points=0 wireframe=0 solid=0 culling=16 synchronized=2
expect-grade cube -DDRAWS_NOTHING: points=0 wireframe=0 solid=0 culling=4 hfov=0 vfov=0 simple_clipping=3 resize=0 synchronized=0
"""
import math
import sys

import close2gl_trace  # [trace] (its read_scene reads the scene)
from model import load_model

IGNORES_FRONT_FACE = "-DIGNORES_FRONT_FACE" in sys.argv
ALWAYS_CULLS = "-DALWAYS_CULLS" in sys.argv
DRAWS_NOTHING = "-DDRAWS_NOTHING" in sys.argv


def rotated(a, b, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return (tuple(c * x + s * y for x, y in zip(a, b)), tuple(c * y - s * x for x, y in zip(a, b)))


def normalized(a):
    k = math.sqrt(sum(x * x for x in a))
    return tuple(x / k for x in a)


def crossed(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def moved(camera, motion, target):
    kind, axis, amount = motion
    pos, u, v, n = camera
    if kind == "rotate":
        if axis == "u":
            v, n = rotated(v, n, amount)
        elif axis == "v":
            n, u = rotated(n, u, amount)
        else:
            u, v = rotated(u, v, amount)
        return pos, u, v, n
    step = {"u": u, "v": v, "n": n}[axis]
    pos = tuple(p + amount * q for p, q in zip(pos, step))
    if kind == "orbit":
        n = normalized(tuple(p - q for p, q in zip(pos, target)))
        if axis == "u":
            u = normalized(crossed(v, n))
            v = crossed(n, u)
        else:
            v = normalized(crossed(n, u))
            u = crossed(v, n)
    return pos, u, v, n


def transform(m, p):
    return tuple(m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] for r in range(4))


def main(scene_path, trace_path):
    scene = close2gl_trace.read_scene(scene_path)
    mesh = load_model(scene.model)
    lo = tuple(min(p[k] for t in mesh for p in t) for k in range(3))
    hi = tuple(max(p[k] for t in mesh for p in t) for k in range(3))
    centre, radius = tuple((a + b) / 2 for a, b in zip(lo, hi)), math.dist(lo, hi) / 2
    if scene.framed:
        d = radius / math.sin(math.radians(min(scene.hfov, scene.vfov) / 2))
        camera = ((centre[0], centre[1], centre[2] + d), (1, 0, 0), (0, 1, 0), (0, 0, 1))
        near = scene.near or (d - radius) / 2
        far = scene.far or d + 2 * radius
    else:
        camera = (scene.position, scene.u, scene.v, scene.n)
        near, far = scene.near, scene.far
    for motion in scene.motions:
        camera = moved(camera, motion, scene.lookat or centre)
    pos, u, v, n = camera
    view = (*u, -sum(a * b for a, b in zip(u, pos)), *v, -sum(a * b for a, b in zip(v, pos)),
            *n, -sum(a * b for a, b in zip(n, pos)), 0, 0, 0, 1)
    sx, sy = 1 / math.tan(math.radians(scene.hfov / 2)), 1 / math.tan(math.radians(scene.vfov / 2))
    proj = (sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, (far + near) / (near - far), 2 * far * near / (near - far),
            0, 0, -1, 0)
    front = "ccw" if IGNORES_FRONT_FACE else scene.culling
    culls = scene.culling != "off" or ALWAYS_CULLS
    if ALWAYS_CULLS and scene.culling == "off":
        front = "ccw"

    with open(trace_path, "w") as f:  # [trace]
        out = close2gl_trace.TraceWriter(f)  # [trace]
        out.window(*scene.window)  # [trace]
        out.ortho2d_ndc()  # [trace]
        out.camera(pos, u, v, n, scene.hfov, scene.vfov, near, far)  # [trace]
        out.culling(scene.culling, "ndc")  # [trace]
        out.clipping("simple near_far")  # [trace]
        out.mode(scene.mode)  # [trace]
        out.matrix("M", view)  # [trace]
        out.matrix("P", proj)  # [trace]
        for index, triangle in enumerate(mesh):
            clip = [transform(proj, transform(view, p)) for p in triangle]
            ndc = None
            if all(-w <= z <= w for _, _, z, w in clip):
                ndc = [(x / w, y / w, z / w) for x, y, z, w in clip]
                (x0, y0, _), (x1, y1, _), (x2, y2, _) = ndc
                twice = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
                if culls and (twice <= 0 if front == "ccw" else twice >= 0):
                    ndc = None
            if DRAWS_NOTHING:
                ndc = None
            out.triangle(index, clip, ndc)  # [trace]
        out.end()  # [trace]


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
