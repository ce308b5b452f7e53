"""The corpus's Python programs' shared minimal model loader (model.h's twin).

load_model(path) -> a list of triangles, each three (x, y, z) corners, in the file's order: the
.in format's v0, v1, v2 lines, or an .obj's v and f lines (polygons as fans from the first
corner). Raises ValueError("path:line: expected ...")."""


def _corner(field, vertices, where):
    i = int(field.split("/")[0])
    i = i + len(vertices) if i < 0 else i - 1
    if not 0 <= i < len(vertices):
        raise ValueError(f"{where}: expected a known vertex, found '{field}'")
    return vertices[i]


def load_model(path):
    obj = path.lower().endswith(".obj")
    vertices, triangles, corners = [], [], []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            where = f"{path}:{number}"
            if not fields:
                continue
            if not obj and fields[0] in ("v0", "v1", "v2"):
                corners.append(tuple(float(x) for x in fields[1:4]))
                if fields[0] == "v2":
                    triangles.append(corners)
                    corners = []
            elif obj and fields[0] == "v":
                vertices.append(tuple(float(x) for x in fields[1:4]))
            elif obj and fields[0] == "f":
                ring = [_corner(x, vertices, where) for x in fields[1:]]
                triangles += [[ring[0], ring[k], ring[k + 1]] for k in range(1, len(ring) - 1)]
    if not triangles:
        raise ValueError(f"{path}: expected at least one triangle")
    return triangles
