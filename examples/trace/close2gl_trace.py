"""close2gl_trace: read a close2gl scene file and write a close2gl trace (format version 1).

The Python twin of close2gl_trace.h, standard library only: copy this file next to your program.

    from close2gl_trace import read_scene, TraceWriter

    scene = read_scene("view.scene")    # or ValueError("view.scene:5: expected ..., found ...")
    mesh = load_model(scene.model)      # your loader; the path is relative to the scene's folder
    camera = frame(mesh, scene.hfov, scene.vfov) if scene.framed else Camera(scene.position,
             scene.u, scene.v, scene.n, scene.hfov, scene.vfov, scene.near, scene.far)
    for kind, axis, amount in scene.motions:   # ("rotate", "v", 10.0), ... in the file's order
        camera.apply(kind, axis, amount)

    with open("frame.trace", "w") as f:
        t = TraceWriter(f)              # writes "close2gl-trace 1"
        t.window(640, 480)
        t.camera(c, u, v, n, hfov, vfov, near, far)
        t.matrix("M", M)                # 16 numbers row by row, or 4 rows of 4
        for i in range(len(triangles)):  # one call per mesh triangle: its clip line, and
            t.triangle(i, clip[i], corners[i] if drawn[i] else None)  # what was drawn of it
        t.end()                         # writes "drawn N" (the tri and poly lines), then "end"

Numbers are written with repr(), the shortest text that reads back as the very same float.
Matrices and corners may be lists, tuples or numpy arrays.
"""

import math
import os
import re

__all__ = ["Scene", "read_scene", "TraceWriter"]

# A number as C's %d, %f, %e or %g print one: no nan, no inf, no hex.
_NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?\Z")

_CAMERA_KEYS = ("position", "u", "v", "n", "hfov", "vfov", "near", "far")
_CHOICES = {"culling": ("off", "ccw", "cw"), "clipping": ("simple", "full", "none"),
            "mode": ("points", "wireframe", "solid"),
            # the rasterizer assignment's (docs/raster-trace-format.md)
            "shading": ("none", "gouraud_ad", "gouraud_ads", "phong"),
            "filter": ("nearest", "bilinear", "trilinear")}
_MOTIONS = {"move": ("move u|v|n D", "uvn", "D"), "rotate": ("rotate u|v|n DEG", "uvn", "DEG"),
            "orbit": ("orbit u|v D", "uv", "D")}
_SCENE_LINE = ("a scene line (model, window, camera, culling, clipping, mode, lookat, move, "
               "rotate, orbit, shading, color, background, light, texture, filter or end)")


class Scene(dict):
    """A scene as a dict whose keys are also attributes (scene.window == scene["window"]).

    model: path; window: (W, H); framed: bool; position, u, v, n: (x, y, z) or None when framed;
    hfov, vfov: degrees (framed and not given: 60.0); near, far: floats (None: framed, not given);
    culling: "off"|"ccw"|"cw"; clipping: "simple"|"full"|"none"; mode: "points"|"wireframe"|"solid";
    lookat: (x, y, z) or None (the model's bounding-box centre);
    motions: [(kind, axis, amount)] with kind "move"|"rotate"|"orbit", in order.
    The rasterizer assignment's lines: shading: "none"|"gouraud_ad"|"gouraud_ads"|"phong";
    color, background: (r, g, b) in [0, 1] (default (1, 1, 1) and (0, 0, 0)); light: (x, y, z)
    (default (10, 10, 3)); texture: path (relative to the scene's folder) or None;
    filter: "nearest"|"bilinear"|"trilinear".
    """

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    __setattr__ = dict.__setitem__


def _shown(text):
    """text as messages quote it: 60 characters at most, control characters as '?'."""
    out = "".join("?" if ord(c) < 32 or 127 <= ord(c) < 160 else c for c in text[:60])
    return out + ("\u2026" if len(text) > 60 else "")


def _shortest(x):
    """2.0, 0.1, 1e-7: the shortest digits that read back (as close2gl's messages print them)."""
    return re.sub(r"e([+-])0*(\d)", lambda m: "e" + m.group(1).strip("+") + m.group(2), repr(x))


def read_scene(path):
    """Reads a `close2gl-scene 1` file; raises ValueError("file:line: expected ..., found ...")."""
    scene = Scene(model=None, window=None, framed=False, position=None, u=None, v=None, n=None,
                  hfov=60.0, vfov=60.0, near=None, far=None, culling="off", clipping="simple",
                  mode="solid", lookat=None, motions=[], shading="none", color=(1.0, 1.0, 1.0),
                  background=(0.0, 0.0, 0.0), light=(10.0, 10.0, 3.0), texture=None,
                  filter="nearest")
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise ValueError(f"{path}:0: cannot read: {e.strerror}") from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as e:
        line = data[:e.start].count(b"\n") + 1
        raise ValueError(f"{path}:{line}: expected UTF-8 text, found the byte "
                         f"0x{data[e.start]:02x}") from None
    lines = text[1:] if text.startswith("\ufeff") else text  # a byte-order mark
    lines = lines.split("\n")
    last = max(1, len(lines) - (lines[-1] == ""))  # a final "\n" does not start another line
    seen = {}  # a key given once -> its line
    magic = False
    end = None
    for number, raw in enumerate(lines, 1):
        raw = raw[:-1] if raw.endswith("\r") else raw
        line = raw.split("#", 1)[0].strip(" \t")  # a comment runs to the end of the line
        fields = [f for f in re.split(r"[ \t]+", line) if f]
        if not fields:
            continue

        def fail(what, found=line):
            raise ValueError(f"{path}:{number}: expected {what}, found '{_shown(found)}'")

        def shape(count, form):
            if len(fields) != count:
                fail(f"'{form}'")

        def num(i, name, form):
            if not _NUMBER.match(fields[i]):
                fail(f"a number for {name} in '{form}'", fields[i])
            x = float(fields[i])
            if not math.isfinite(x):  # 1e999
                fail(f"a finite number for {name} in '{form}'", fields[i])
            return x

        def xyz(first, form):
            return tuple(num(first + k, "XYZ"[k], form) for k in range(3))

        def once(key):
            if key in seen:
                fail(f"one '{key}' line (the first is line {seen[key]})")
            seen[key] = number

        key = fields[0]
        if not magic:  # the first line: the version
            if fields == ["close2gl-scene", "1"]:
                magic = True
                continue
            note = ""
            if len(fields) == 2 and key == "close2gl-scene":
                note = " (this close2gl reads version 1)"
            elif key == "close2gl-trace":
                note = " (a trace file, not a scene)"
            raise ValueError(f"{path}:{number}: expected 'close2gl-scene 1', "
                             f"found '{_shown(line)}'{note}")
        if end:
            fail(f"nothing after 'end' (line {end})")
        if key == "camera":
            which = fields[1] if len(fields) > 1 else ""
            pose = [seen[f"camera {k}"] for k in _CAMERA_KEYS[:4] if f"camera {k}" in seen]
            if which == "framed":
                shape(2, "camera framed")
                if pose:
                    fail(f"'camera framed' or a pose (line {min(pose)}), not both")
                once("camera framed")
                scene.framed = True
            elif which in _CAMERA_KEYS[:4] and "camera framed" in seen:
                fail(f"only 'camera hfov|vfov|near|far' after 'camera framed' "
                     f"(line {seen['camera framed']})")
            elif which not in _CAMERA_KEYS:
                fail("'camera position|u|v|n X Y Z' or 'camera hfov|vfov|near|far D'")
            elif which in _CAMERA_KEYS[:4]:
                shape(5, f"camera {which} X Y Z")
                value = xyz(2, f"camera {which} X Y Z")
                once(f"camera {which}")
                scene[which] = value
            else:
                name = "DEG" if which in ("hfov", "vfov") else "D"
                form = f"camera {which} {name}"
                shape(3, form)
                x = num(2, name, form)
                if name == "DEG" and not 0 < x < 180:
                    fail(f"'{form}' with DEG in (0, 180)")
                if name == "D" and not x > 0:
                    fail(f"'{form}' with D > 0")
                if which == "near" and scene.far is not None and not x < scene.far:
                    fail(f"'{form}' with D < far ({_shortest(scene.far)}, "
                         f"line {seen['camera far']})")
                if which == "far" and scene.near is not None and not x > scene.near:
                    fail(f"'{form}' with D > near ({_shortest(scene.near)}, "
                         f"line {seen['camera near']})")
                once(f"camera {which}")
                scene[which] = x
        elif key == "model":
            shape(2, "model PATH")
            once("model")
            # A relative PATH is relative to the scene file's folder.
            scene.model = os.path.join(os.path.dirname(path), fields[1])
        elif key == "texture":
            shape(2, "texture PATH")
            once("texture")
            scene.texture = os.path.join(os.path.dirname(path), fields[1])
        elif key in ("color", "background"):
            form = f"{key} R G B"
            shape(4, form)
            value = tuple(num(1 + k, "RGB"[k], form) for k in range(3))
            if not all(0 <= x <= 1 for x in value):
                fail(f"'{form}' with R, G and B in [0, 1]")
            once(key)
            scene[key] = value
        elif key == "light":
            shape(4, "light X Y Z")
            value = xyz(1, "light X Y Z")
            once("light")
            scene.light = value
        elif key == "window":
            shape(3, "window W H")
            size = []
            for i, name in ((1, "W"), (2, "H")):
                if not re.match(r"\+?[0-9]+\Z", fields[i]):
                    fail(f"a non-negative integer for {name} in 'window W H'", fields[i])
                if not 1 <= int(fields[i]) <= 16384:
                    fail("'window W H' with W and H in 1..=16384")
                size.append(int(fields[i]))
            once("window")
            scene.window = tuple(size)
        elif key in _CHOICES:
            form = f"{key} {'|'.join(_CHOICES[key])}"
            shape(2, form)
            if fields[1] not in _CHOICES[key]:
                fail(f"'{form}'")
            once(key)
            scene[key] = fields[1]
        elif key == "lookat":
            shape(4, "lookat X Y Z")
            value = xyz(1, "lookat X Y Z")
            once("lookat")
            scene.lookat = value
        elif key in _MOTIONS:
            form, axes, name = _MOTIONS[key]
            shape(3, form)
            if len(fields[1]) != 1 or fields[1] not in axes:
                fail(f"'{form}'")
            scene.motions.append((key, fields[1], num(2, name, form)))
        elif key == "end":
            shape(1, "end")
            end = number
        else:
            fail(_SCENE_LINE)

    # The whole file is read: what is missing is reported at its last line.
    if not magic:
        raise ValueError(f"{path}:{last}: expected 'close2gl-scene 1', found end of file")
    missing = None
    if "model" not in seen:
        missing = "'model PATH'"
    elif "window" not in seen:
        missing = "'window W H'"
    elif not scene.framed:
        if not any(f"camera {k}" in seen for k in _CAMERA_KEYS[:4]):
            missing = "'camera framed' or 'camera position X Y Z'"
        else:
            for k in _CAMERA_KEYS:
                if f"camera {k}" not in seen:
                    numbers = "X Y Z" if k in _CAMERA_KEYS[:4] else "DEG" if "fov" in k else "D"
                    missing = missing or f"'camera {k} {numbers}'"
    if missing:
        raise ValueError(f"{path}:{last}: the scene ends without {missing}")
    return scene


def _flat(values):
    """Numbers, or lists, tuples or arrays of them (corners, matrix rows), as one flat list."""
    out = []
    for x in values:
        out.extend(_flat(x) if hasattr(x, "__iter__") else [x])
    return out


class TraceWriter:
    """Writes a `close2gl-trace 1` file, one method per kind of line, to an open text file."""

    def __init__(self, file):
        self.file = file
        self.pieces = 0  # the tri and poly lines written, for `drawn N`
        self.output = False  # whether any clip, tri or poly line says the 2D output is given
        file.write("close2gl-trace 1\n")

    def _line(self, head, numbers=()):
        text = " ".join([head] + [repr(float(x)) for x in _flat(numbers)])
        self.file.write(text + "\n")

    def model(self, name):
        # One field: spaces and '#' would break the line.
        self._line("model " + re.sub(r"[\s#]", "_", name))

    def triangles(self, count):
        self._line(f"triangles {int(count)}")

    def window(self, width, height):
        self._line(f"window {int(width)} {int(height)}")

    def ortho2d(self, left, right, bottom, top):
        self._line("ortho2d", (left, right, bottom, top))

    def ortho2d_ndc(self):
        """NDC output (the GPU does the viewport): ortho2d -1 1 -1 1."""
        self.ortho2d(-1, 1, -1, 1)

    def camera(self, position, u, v, n, hfov, vfov, near, far):
        """The eight camera lines."""
        for key, value in (("position", position), ("u", u), ("v", v), ("n", n), ("hfov", [hfov]),
                           ("vfov", [vfov]), ("near", [near]), ("far", [far])):
            self._line("camera " + key, value)

    def culling(self, culling, space=None):
        """culling "off", "ccw" or "cw"; space None (as seen on screen), "ndc" or "window"."""
        assert culling in _CHOICES["culling"] and space in (None, "ndc", "window")
        self._line("culling " + culling + (f" {space}" if space and culling != "off" else ""))

    def clipping(self, clipping):
        """clipping "simple", "full", "none", "simple near_far" or "full near_far"."""
        assert clipping in _CHOICES["clipping"] + ("simple near_far", "full near_far")
        self._line("clipping " + clipping)

    def mode(self, mode):
        assert mode in _CHOICES["mode"]
        self._line("mode " + mode)

    def matrix(self, which, m, columns=False):
        """which: "M", "P", "V" or "model" (the model matrix, applied before M); m: 16 numbers or
        4 rows of 4, row by row (a 4x4 numpy array is rows); columns=True for one kept column by
        column, as OpenGL and glm keep them (PyGLM's matrices, a flat glGet array)."""
        flat = _flat(m)
        assert which in ("M", "P", "V", "model") and len(flat) == 16
        if columns:
            flat = [flat[4 * (i % 4) + i // 4] for i in range(16)]
        self._line("matrix " + which, flat)

    def clip(self, t, corners):
        """Mesh triangle t's corners in clip coordinates: 12 numbers, or 3 (x, y, z, w)."""
        assert len(_flat(corners)) == 12
        self.output = True
        self._line(f"clip {int(t)}", corners)

    def tri(self, t, corners):
        """A drawn 2D triangle: 3 corners (x, y) or (x, y, z NDC depth), or 6 or 9 numbers."""
        assert len(_flat(corners)) in (6, 9)
        self.output, self.pieces = True, self.pieces + 1
        self._line(f"tri {int(t)}", corners)

    def poly(self, t, corners):
        """A drawn polygon: a list of K >= 3 corners (x, y) or (x, y, z)."""
        k, flat = len(corners), _flat(corners)
        assert k >= 3 and len(flat) in (2 * k, 3 * k)
        self.output, self.pieces = True, self.pieces + 1
        self._line(f"poly {int(t)} {k}", flat)

    def triangle(self, t, clip=None, corners=None):
        """Mesh triangle t in one call: its clip line (when clip is given), then what was drawn
        of it: corners None (not drawn), 3 corners (a tri line) or more (a poly line)."""
        self.output = True
        if clip is not None:
            self.clip(t, clip)
        if corners is not None:
            (self.tri if len(corners) == 3 else self.poly)(t, corners)

    def end(self):
        """`drawn N` when the trace gave its 2D output (any clip, tri or poly line), then `end`."""
        if self.output:
            self._line(f"drawn {self.pieces}")
        self._line("end")
