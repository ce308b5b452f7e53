"""rcommon.h's Python twin: the raster corpus's shared model reader (positions, vertex normals,
s t) and the first assignment's camera (framing, moves, M and P), not what differs between
students' rasterizers.

load(path) -> (triangles, textured): each triangle (p, n, uv), three corners each.
camera(scene, triangles) -> (M, P): 4x4 lists, row by row.
"""
import math

IA, IL = (0.3, 1.0, 0.3), (1.0, 1.0, 1.0)
KA, KD, KS, SHININESS = 0.3, 0.8, 0.5, 10.0
ATT = (0.01, 0.001, 0.0)


def load(path):
    obj = path.lower().endswith(".obj")
    tris, textured = [], not obj
    v, vt, vn = [], [], []
    corners = {}
    all_vt = True
    with open(path) as f:
        for number, line in enumerate(f, 1):
            x = line.split()
            if not x:
                continue
            if not obj:
                if x[0] == "Texture" and len(x) == 3:
                    textured = x[2] == "YES"
                elif x[0] in ("v0", "v1", "v2"):
                    nums = [float(a) for a in x[1:]]
                    uv = (nums[7], nums[8]) if textured else (0.0, 0.0)
                    corners[x[0]] = (tuple(nums[0:3]), tuple(nums[3:6]), uv)
                    if x[0] == "v2":
                        c = [corners["v0"], corners["v1"], corners["v2"]]
                        tris.append(([a[0] for a in c], [a[1] for a in c], [a[2] for a in c]))
            elif x[0] in ("v", "vt", "vn"):
                {"v": v, "vt": vt, "vn": vn}[x[0]].append(tuple(float(a) for a in x[1:4]))
            elif x[0] == "f":
                idx = []
                for field in x[1:]:
                    parts = (field.split("/") + ["", ""])[:3]
                    lists = (v, vt, vn)
                    idx.append([(int(p) - 1 if int(p) > 0 else len(lists[k]) + int(p)) if p else -1
                                for k, p in enumerate(parts)])
                all_vt = all_vt and all(i[1] >= 0 for i in idx)
                for k in range(1, len(idx) - 1):
                    c = [idx[0], idx[k], idx[k + 1]]
                    p = [v[i[0]] for i in c]
                    e1 = [p[1][a] - p[0][a] for a in range(3)]
                    e2 = [p[2][a] - p[0][a] for a in range(3)]
                    face = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                            e1[0] * e2[1] - e1[1] * e2[0]]
                    length = math.sqrt(sum(a * a for a in face)) or 1.0
                    n = [vn[i[2]] if i[2] >= 0 else tuple(a / length for a in face) for i in c]
                    uv = [vt[i[1]][:2] if i[1] >= 0 else (0.0, 0.0) for i in c]
                    tris.append((p, n, uv))
    if obj:
        textured = all_vt and bool(tris)
    if not tris:
        raise ValueError(f"{path}: expected at least one triangle")
    return tris, textured


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _unit(a):
    length = math.sqrt(sum(x * x for x in a))
    return [x / length for x in a]


def camera(s, tris):
    pts = [p for t in tris for p in t[0]]
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
    r = 0.5 * math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3)))
    if s.framed:
        r = r if r > 0 else 1.0
        d = r / math.sin(math.radians(min(s.hfov, s.vfov)) / 2)
        c, u, v, n = [centre[0], centre[1], centre[2] + d], [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]
        near = s.near if s.near is not None else 0.5 * (d - r)
        if not near > 0:
            near = 0.01 * r
        far = s.far if s.far is not None else d + 2 * r
        if far <= near:
            if s.near is not None:
                far = near + 2 * r
            else:
                near = 0.01 * far
    else:
        c, u, v, n = list(s.position), list(s.u), list(s.v), list(s.n)
        near, far = s.near, s.far
    look = list(s.lookat) if s.lookat is not None else centre
    for kind, axis, amount in s.motions:
        a = math.radians(amount)
        cs, sn = math.cos(a), math.sin(a)
        if kind == "move":
            ax = {"u": u, "v": v, "n": n}[axis]
            c = [c[k] + ax[k] * amount for k in range(3)]
        elif kind == "rotate":
            if axis == "u":
                v, n = [v[k] * cs + n[k] * sn for k in range(3)], [n[k] * cs - v[k] * sn for k in range(3)]
            elif axis == "v":
                n, u = [n[k] * cs + u[k] * sn for k in range(3)], [u[k] * cs - n[k] * sn for k in range(3)]
            else:
                u, v = [u[k] * cs + v[k] * sn for k in range(3)], [v[k] * cs - u[k] * sn for k in range(3)]
        else:
            ax = u if axis == "u" else v
            c = [c[k] + ax[k] * amount for k in range(3)]
            n = _unit([c[k] - look[k] for k in range(3)])
            if axis == "u":
                u = _unit(_cross(v, n))
                v = _cross(n, u)
            else:
                v = _unit(_cross(n, u))
                u = _cross(v, n)
    M = [u + [-sum(c[k] * u[k] for k in range(3))], v + [-sum(c[k] * v[k] for k in range(3))],
         n + [-sum(c[k] * n[k] for k in range(3))], [0.0, 0.0, 0.0, 1.0]]
    top, right = near * math.tan(math.radians(s.vfov) / 2), near * math.tan(math.radians(s.hfov) / 2)
    P = [[near / right, 0, 0, 0], [0, near / top, 0, 0],
         [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)], [0, 0, -1.0, 0]]
    return M, P
