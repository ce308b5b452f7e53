"""close2gl_raster: write a close2gl raster trace (format version 1) and its two buffers, and read a
PPM texture. The Python twin of close2gl_raster.h, standard library only (numpy arrays are taken
when given, never required): copy this file next to your program. See
docs/raster-trace-format.md.

    from close2gl_raster import RasterWriter, write_buffers, read_ppm

    with open("frame.raster", "w") as f:
        r = RasterWriter(f)                 # writes "close2gl-raster 1"
        r.window(W, H)
        r.subpixel(8)                       # if your rasterizer snaps to 1/256 pixel
        r.shading("phong")
        r.light(light); r.matrix(M); r.lighting(ia, il, ka, kd, ks, n, (c0, c1, c2))
        r.buffer_names("frame.raster")      # framebuffer frame.raster.ppm, depthbuffer .pfm
        r.attributes("eye", "normal")       # window x y z q come first, always
        for t, corners in rasterized:       # in the order you rasterized them
            r.tri(t, corners)               # 3 corners of 4 + 3 + 3 numbers (or 30 numbers)
        r.end()                             # "drawn N", then "end"
    write_buffers("frame.raster", rgb, depth, W, H, top_row_first=True)  # both files

Numbers are written with repr(), the shortest text that reads back as the very same float.
"""

import os
import re
import struct

__all__ = ["RasterWriter", "write_ppm", "write_pfm", "write_buffers", "read_ppm"]

_SHADINGS = ("none", "gouraud_ad", "gouraud_ads", "phong")
_FILTERS = ("nearest", "bilinear", "trilinear")
_ATTRIBUTES = {"rgb": 3, "eye": 3, "normal": 3, "uv": 2}  # in the order a trace gives them


def _flat(values):
    """Numbers, or lists, tuples or arrays of them (corners, matrix rows), as one flat list."""
    if hasattr(values, "ravel"):  # numpy
        return [float(x) for x in values.ravel()]
    out = []
    for x in values:
        out.extend(_flat(x) if hasattr(x, "__iter__") else [x])
    return out


def _field(text):
    """One field: blanks and '#' would break the line."""
    return re.sub(r"[\s#]", "_", str(text))


class RasterWriter:
    """Writes a `close2gl-raster 1` file, one method per kind of line, to an open text file."""

    def __init__(self, file):
        self.file = file
        self.tris = 0  # the tri lines written, for `drawn N`
        self.per_corner = 4
        file.write("close2gl-raster 1\n")

    def _line(self, head, numbers=()):
        self.file.write(" ".join([head] + [repr(float(x)) for x in _flat(numbers)]) + "\n")

    def model(self, name):
        self._line("model " + _field(name))

    def window(self, width, height):
        self._line(f"window {int(width)} {int(height)}")

    def origin(self, origin):
        """"bottom-left" (OpenGL's, the default) or "top-left" (rows counted from the top)."""
        assert origin in ("bottom-left", "top-left")
        self._line("origin " + origin)

    def subpixel(self, bits):
        """Window x, y snapped to 1/2^bits pixel before deciding coverage."""
        self._line(f"subpixel {int(bits)}")

    def shading(self, shading):
        assert shading in _SHADINGS
        self._line("shading " + shading)

    def color(self, rgb):
        self._line("color", rgb)

    def background(self, rgb):
        self._line("background", rgb)

    def light(self, position):
        """The light's position in world coordinates."""
        self._line("light", position)

    def matrix(self, m, columns=False):
        """The modelview M: 16 numbers or 4 rows of 4, row by row (a 4x4 numpy array is rows);
        columns=True for one kept column by column (OpenGL's and glm's order)."""
        flat = _flat(m)
        assert len(flat) == 16
        if columns:
            flat = [flat[4 * (i % 4) + i // 4] for i in range(16)]
        self._line("matrix M", flat)

    def lighting(self, ia, il, ka, kd, ks, shininess, attenuation):
        """Ia (r, g, b), Il (r, g, b), ka, kd, ks, the shininess n, attenuation (c0, c1, c2)."""
        numbers = _flat([ia, il, [ka, kd, ks, shininess], attenuation])
        assert len(numbers) == 13
        self._line("lighting", numbers)

    def texture(self, path, filter="nearest"):
        """The texture sampled (a PPM, relative to the trace's folder) and its filter."""
        assert filter in _FILTERS
        self._line("texture " + _field(path))
        self._line("filter " + filter)

    def framebuffer(self, path):
        self._line("framebuffer " + _field(path))

    def depthbuffer(self, path):
        self._line("depthbuffer " + _field(path))

    def buffer_names(self, trace_path):
        """Both lines for the buffers write_buffers(trace_path, ...) writes beside the trace:
        `framebuffer NAME.ppm` and `depthbuffer NAME.pfm`, NAME the trace's file name."""
        name = os.path.basename(trace_path)
        self.framebuffer(name + ".ppm")
        self.depthbuffer(name + ".pfm")

    def attributes(self, *names):
        """Any of "rgb", "eye", "normal", "uv" after the window's x y z q (written in that
        order whatever the order given)."""
        assert all(n in _ATTRIBUTES for n in names)
        ordered = [n for n in _ATTRIBUTES if n in names]
        self.per_corner = 4 + sum(_ATTRIBUTES[n] for n in ordered)
        self._line(" ".join(["attributes", "window"] + ordered))

    def tri(self, t, corners):
        """A triangle rasterized for mesh triangle t: 3 corners, each x y z q then the
        attributes (3 lists or a flat list of 3 x per-corner numbers, or a numpy array)."""
        flat = _flat(corners)
        assert len(flat) == 3 * self.per_corner, f"{len(flat)} numbers, not 3 x {self.per_corner}"
        self.tris += 1
        self._line(f"tri {int(t)}", flat)

    def end(self):
        """`drawn N` (the tri lines written), then `end`."""
        self._line(f"drawn {self.tris}")
        self._line("end")


def _rows(pixels, width, height, per_pixel, top_row_first):
    """The rows of pixels (a flat sequence, bytes, or a numpy array (H, W[, C])) from the top."""
    if hasattr(pixels, "ravel"):
        pixels = pixels.ravel().tolist()
    elif isinstance(pixels, (bytes, bytearray, memoryview)):
        pixels = list(bytes(pixels))
    else:
        pixels = _flat(pixels)
    size = width * per_pixel
    assert len(pixels) == height * size, f"{len(pixels)} values for {width}x{height}x{per_pixel}"
    rows = [pixels[y * size:(y + 1) * size] for y in range(height)]
    return rows if top_row_first else rows[::-1]


def write_ppm(path, rgb, width, height, top_row_first=True):
    """The colour buffer as a P6 PPM (top row first, as PPM says): rgb is width*height*3 bytes
    or numbers 0..255, a flat sequence or an (H, W, 3) numpy array; top_row_first says how
    your array is laid out."""
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height))
        for row in _rows(rgb, width, height, 3, top_row_first):
            f.write(bytes(int(x) for x in row))


def write_pfm(path, depth, width, height, top_row_first=True):
    """The depth buffer as a little-endian Pf PFM (bottom row first, as PFM says): depth is
    width*height floats, a flat sequence or an (H, W) numpy array; top_row_first says how your
    array is laid out."""
    rows = _rows(depth, width, height, 1, top_row_first)
    with open(path, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (width, height))
        for row in reversed(rows):
            f.write(struct.pack("<%df" % width, *row))


def write_buffers(trace_path, rgb, depth, width, height, top_row_first=True):
    """Both buffers beside the trace: TRACE.ppm and TRACE.pfm (depth None: the PPM alone)."""
    write_ppm(trace_path + ".ppm", rgb, width, height, top_row_first)
    if depth is not None:
        write_pfm(trace_path + ".pfm", depth, width, height, top_row_first)


def read_ppm(path):
    """A PPM (P6 or P3, maxval 1..65535, scaled to 0..255): (width, height, rgb bytes top row
    first). Raises ValueError naming the file."""
    with open(path, "rb") as f:
        data = f.read()
    magic, at = data[:2], 2
    if magic not in (b"P6", b"P3"):
        raise ValueError(f"{path}: expected a PPM image (P6 or P3)")

    def token(at):
        while True:
            while at < len(data) and data[at:at + 1].isspace():
                at += 1
            if data[at:at + 1] != b"#":
                break
            while at < len(data) and data[at:at + 1] != b"\n":
                at += 1
        end = at
        while end < len(data) and data[end:end + 1].isdigit():
            end += 1
        if end == at:
            raise ValueError(f"{path}: expected a PPM header 'P6|P3 W H MAXVAL'")
        return int(data[at:end]), end

    width, at = token(at)
    height, at = token(at)
    maxval, at = token(at)
    if not (1 <= width <= 65536 and 1 <= height <= 65536 and 1 <= maxval <= 65535):
        raise ValueError(f"{path}: expected a PPM header 'P6|P3 W H MAXVAL' (W, H in "
                         f"1..65536, MAXVAL in 1..65535)")
    count = width * height * 3
    if magic == b"P3":
        values = [int(x) for x in re.sub(rb"#[^\n]*", b" ", data[at:]).split()[:count]]
    elif maxval < 256:
        values = list(data[at + 1:at + 1 + count])
    else:
        raw = data[at + 1:at + 1 + 2 * count]
        values = list(struct.unpack(">%dH" % (len(raw) // 2), raw))
    if len(values) != count or any(v > maxval for v in values):
        raise ValueError(f"{path}: expected {count} samples in 0..{maxval}")
    if maxval != 255:
        values = [(v * 255 + maxval // 2) // maxval for v in values]
    return width, height, bytes(values)
