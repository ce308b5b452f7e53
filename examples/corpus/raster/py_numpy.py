"""py_numpy.py: a Python 3 rasterizer with numpy (float64), vectorised the way numpy teaches:
every triangle's bounding box (clamped to the window) at once as a grid of pixel centres, its
three edge functions as arrays, a mask of the covered ones (all >= 0: a centre on an edge is in
both triangles, which check cannot see without a `subpixel` line), then depth, the z-buffer
test and the shading on the masked pixels together. Window coordinates y down (row 0 at the
top). Near-plane clipping only (the box is clamped: a guard band), culling by the winding on
screen. Varyings perspective-correct; shading none, Gouraud, Phong; textures nearest, bilinear,
trilinear (λ from the quad's three pixels, evaluated like any pixel).

    PYTHONPATH=../../trace:../../raster python3 py_numpy.py SCENE TRACE [-DVARIANT ...]

Needs numpy (Debian: apt-get install python3-numpy; CI installs it).

Variants, each a bug students make:
  -DNORMALS_UNNORMALIZED  Phong's interpolated normal used as it comes (normal_not_renormalized):
                          seen on the knot's smooth normals, not on the cube's flat faces
  -DZ_PERSPECTIVE         depth blended like every varying, with 1/w (depth_perspective)

Lines ending in "[trace]" were added only to write the trace.

expect square: agree
expect cube_flat: agree
expect cube_gouraud_ads: agree
expect knot_phong: agree
expect floor_trilinear: agree
expect cube_nearest: agree
expect knot_phong -DNORMALS_UNNORMALIZED: differs mistakes=normal_not_renormalized
expect cube_phong -DNORMALS_UNNORMALIZED: agree
expect cube_flat -DZ_PERSPECTIVE: differs mistakes=depth_perspective
expect knot_phong -DZ_PERSPECTIVE: differs mistakes=depth_perspective
expect square -DZ_PERSPECTIVE: agree
expect-grade: 200
expect-grade -DNORMALS_UNNORMALIZED: phong=12 resize=7 synchronized=13
expect-grade -DZ_PERSPECTIVE: zbuffer=10 resize=0 synchronized=1
  (predicted before grading: synchronized=2, for 15 scenes; the rubric has 16: 15 x 2 / 16 = 1)
"""
import os
import sys

import numpy as np

from close2gl_raster import RasterWriter, read_ppm, write_buffers, write_ppm  # [trace]
from close2gl_trace import read_scene
import rcommon

FLAGS = set(sys.argv[3:])
NORMALS_UNNORMALIZED = "-DNORMALS_UNNORMALIZED" in FLAGS
Z_PERSPECTIVE = "-DZ_PERSPECTIVE" in FLAGS


def unit(v):
    return v / np.sqrt(np.maximum((v * v).sum(-1, keepdims=True), 1e-30))


def illuminate(eye, normal, specular, light_eye, color, renormalize=True):
    """The lecture's lighting at rows of eye positions and normals (N, 3)."""
    n = unit(normal) if renormalize else normal
    to_light = light_eye - eye
    d = np.sqrt((to_light * to_light).sum(-1, keepdims=True))
    l, v = to_light / d, unit(-eye)
    nl = (n * l).sum(-1, keepdims=True)
    r = 2 * nl * n - l
    f = np.minimum(1 / (rcommon.ATT[0] + rcommon.ATT[1] * d + rcommon.ATT[2] * d * d), 1)
    lit = rcommon.KD * np.maximum(nl, 0)
    if specular:
        lit = lit + rcommon.KS * np.maximum((v * r).sum(-1, keepdims=True), 0) ** rcommon.SHININESS
    return color * (np.array(rcommon.IA) * rcommon.KA + np.array(rcommon.IL) * f * lit)


def mip_chain(base):
    levels = [base]
    while levels[-1].shape[0] > 1 or levels[-1].shape[1] > 1:
        a = levels[-1]
        h, w = max(a.shape[0] // 2, 1), max(a.shape[1] // 2, 1)
        y0, x0 = np.arange(h) * 2, np.arange(w) * 2
        y1, x1 = np.minimum(y0 + 1, a.shape[0] - 1), np.minimum(x0 + 1, a.shape[1] - 1)
        s = (a[y0][:, x0].astype(int) + a[y0][:, x1] + a[y1][:, x0] + a[y1][:, x1])
        levels.append(((s + 2) // 4).astype(np.uint8))
    return levels


def texels(level, x, y):
    h, w = level.shape[:2]
    return level[np.mod(y.astype(np.int64), h), np.mod(x.astype(np.int64), w)] / 255.0


def bilinear(level, s, t):
    h, w = level.shape[:2]
    x, y = s * w - 0.5, (1 - t) * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    top = texels(level, x0, y0) * (1 - fx) + texels(level, x0 + 1, y0) * fx
    bottom = texels(level, x0, y0 + 1) * (1 - fx) + texels(level, x0 + 1, y0 + 1) * fx
    return top * (1 - fy) + bottom * fy


def main():
    if len(sys.argv) < 3:
        print(f"usage: {sys.argv[0]} SCENE TRACE [-DVARIANT ...]", file=sys.stderr)
        return 2
    scene_path, trace_path = sys.argv[1], sys.argv[2]
    try:
        s = read_scene(scene_path)
        tris, textured = rcommon.load(s.model)
    except ValueError as e:
        print(e, file=sys.stderr)
        return 1
    M, P = (np.array(m, dtype=float) for m in rcommon.camera(s, tris))
    W, H = s.window
    color = np.array(s.color)
    light_eye = (M @ np.array(list(s.light) + [1.0]))[:3]
    shading, filt = s.shading, s.filter
    lit = shading != "none"
    gouraud = shading in ("gouraud_ad", "gouraud_ads")
    textured = textured and s.texture is not None
    if textured:
        tw, th, data = read_ppm(s.texture)
        mips = mip_chain(np.frombuffer(data, dtype=np.uint8).reshape(th, tw, 3))
    clear = (np.clip(np.array(s.background), 0, 1) * 255 + 0.5).astype(np.uint8)
    frame = np.tile(clear, (H, W, 1))
    depth = np.ones((H, W), dtype=np.float32)

    # every corner at once: eye, normal, clip, Gouraud's colour
    p = np.array([t[0] for t in tris], dtype=float)            # (T, 3, 3)
    nrm = np.array([t[1] for t in tris], dtype=float)
    uv = np.array([t[2] for t in tris], dtype=float)            # (T, 3, 2)
    eye = p @ M[:3, :3].T + M[:3, 3]
    normal = nrm @ M[:3, :3].T
    clip = eye @ P[:, :3].T + P[:, 3]
    rgb = np.broadcast_to(color, eye.shape).copy()
    if gouraud:
        rgb = illuminate(eye.reshape(-1, 3), normal.reshape(-1, 3), shading == "gouraud_ads",
                         light_eye, color).reshape(eye.shape)
    # per corner: rgb 0:3, eye 3:6, normal 6:9, uv 9:11
    attrs = np.concatenate([rgb, eye, normal, uv], axis=2)

    f = open(trace_path, "w")                                                  # [trace]
    out = RasterWriter(f)                                                      # [trace]
    out.model(os.path.basename(s.model))                                       # [trace]
    out.window(W, H)                                                           # [trace]
    out.origin("top-left")                                                     # [trace]
    out.shading(shading)                                                       # [trace]
    out.color(s.color)                                                         # [trace]
    out.background(s.background)                                               # [trace]
    if lit:                                                                    # [trace]
        out.light(s.light)                                                     # [trace]
        out.matrix(M.tolist())                                                 # [trace]
        out.lighting(rcommon.IA, rcommon.IL, rcommon.KA, rcommon.KD, rcommon.KS,  # [trace]
                     rcommon.SHININESS, rcommon.ATT)                          # [trace]
    texture_name = trace_path + ".texture.ppm"                                # [trace]
    if textured:                                                               # [trace]
        out.texture(os.path.basename(texture_name), filt)                     # [trace]
    out.buffer_names(trace_path)                                               # [trace]
    names = (["rgb"] if gouraud else []) + (["eye", "normal"] if lit else []) + (["uv"] if textured else [])  # [trace]
    out.attributes(*names)                                                     # [trace]
    keep = np.r_[0:3] if gouraud else np.r_[0:0]                              # [trace]
    keep = np.r_[keep, 3:9] if lit else keep                                  # [trace]
    keep = np.r_[keep, 9:11] if textured else keep                            # [trace]

    def draw(win, a):
        """One triangle: win (3, 4) x y(down) z q, a (3, 11)."""
        x, y = win[:, 0], win[:, 1]
        area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])
        if area == 0 or not np.isfinite(area):
            return
        i0, i1 = max(int(np.floor(x.min())), 0), min(int(np.ceil(x.max())), W - 1)
        j0, j1 = max(int(np.floor(y.min())), 0), min(int(np.ceil(y.max())), H - 1)
        if i0 > i1 or j0 > j1:
            return
        jj, ii = np.mgrid[j0:j1 + 1, i0:i1 + 1]

        def weights(px, py):
            w0 = ((x[1] - px) * (y[2] - py) - (x[2] - px) * (y[1] - py)) / area
            w1 = ((x[2] - px) * (y[0] - py) - (x[0] - px) * (y[2] - py)) / area
            return np.stack([w0, w1, 1 - w0 - w1], -1)

        def varying(w, k):
            wq = w * win[:, 3]
            return (wq @ a[:, k]) / wq.sum(-1, keepdims=True)

        px, py = ii.ravel() + 0.5, jj.ravel() + 0.5
        w = weights(px, py)
        w[:, 2] = ((x[0] - px) * (y[1] - py) - (x[1] - px) * (y[0] - py)) / area
        inside = (w >= 0).all(-1)
        if not inside.any():
            return
        w, ii, jj = w[inside], ii.ravel()[inside], jj.ravel()[inside]
        if Z_PERSPECTIVE:
            wq = w * win[:, 3]
            z = ((wq @ win[:, 2]) / wq.sum(-1)).astype(np.float32)   # BUG: depth as a varying
        else:
            z = (w @ win[:, 2]).astype(np.float32)
        passes = z < depth[jj, ii]
        # the same pixel is not twice in one triangle: the test and the write are one step
        w, ii, jj, z = w[passes], ii[passes], jj[passes], z[passes]
        depth[jj, ii] = z
        if shading == "none":
            c = np.broadcast_to(color, (len(z), 3))
        elif shading == "phong":
            c = illuminate(varying(w, np.r_[3:6]), varying(w, np.r_[6:9]), True, light_eye, color,
                           renormalize=not NORMALS_UNNORMALIZED)
        else:
            c = varying(w, np.r_[0:3])
        if textured:
            st = varying(w, np.r_[9:11])
            if filt == "nearest":
                h0, w0 = mips[0].shape[:2]
                tex = texels(mips[0], np.floor(st[:, 0] * w0), np.floor((1 - st[:, 1]) * h0))
            elif filt == "bilinear":
                tex = bilinear(mips[0], st[:, 0], st[:, 1])
            else:
                qx, qy = (ii & ~1) + 0.5, (jj & ~1) + 0.5
                a0, a1, a2 = (varying(weights(bx, by), np.r_[9:11])
                              for bx, by in ((qx, qy), (qx + 1, qy), (qx, qy + 1)))
                size = np.array([mips[0].shape[1], mips[0].shape[0]])
                rho = np.maximum(np.linalg.norm((a1 - a0) * size, axis=-1),
                                 np.linalg.norm((a2 - a0) * size, axis=-1))
                lod = np.clip(np.log2(rho), 0, len(mips) - 1)
                below = np.floor(lod).astype(int)
                tex = np.zeros((len(z), 3))
                for level in np.unique(below):
                    m = below == level
                    frac = (lod[m] - level)[:, None]
                    upper = min(level + 1, len(mips) - 1)
                    tex[m] = (bilinear(mips[level], st[m, 0], st[m, 1]) * (1 - frac)
                              + bilinear(mips[upper], st[m, 0], st[m, 1]) * frac)
            c = c * tex
        frame[jj, ii] = (np.clip(c, 0, 1) * 255 + 0.5).astype(np.uint8)

    for t in range(len(tris)):
        poly = [(clip[t, k], attrs[t, k]) for k in range(3)]
        d = [c[2] + c[3] for c, _ in poly]
        if min(d) < 0:   # the near plane only
            kept = []
            for k in range(3):
                (ca, aa), (cb, ab), da, db = poly[k], poly[(k + 1) % 3], d[k], d[(k + 1) % 3]
                if da >= 0:
                    kept.append((ca, aa))
                if (da >= 0) != (db >= 0):
                    u = da / (da - db)
                    kept.append((ca + (cb - ca) * u, aa + (ab - aa) * u))
            poly = kept
        if len(poly) < 3:
            continue
        cs = np.array([c for c, _ in poly])
        q = 1 / cs[:, 3]
        win = np.stack([(cs[:, 0] * q + 1) * W / 2, (1 - cs[:, 1] * q) * H / 2,
                        cs[:, 2] * q * 0.5 + 0.5, q], -1)
        a = np.array([x for _, x in poly])
        area = (win[:, 0] * np.roll(win[:, 1], -1) - np.roll(win[:, 0], -1) * win[:, 1]).sum()
        if (s.culling == "ccw" and area >= 0) or (s.culling == "cw" and area <= 0):
            continue
        for k in range(1, len(poly) - 1):
            fan = [0, k, k + 1]
            out.tri(t, np.concatenate([win[fan], a[fan][:, keep]], axis=1))  # [trace]
            draw(win[fan], a[fan])
    out.end()                                                                  # [trace]
    f.close()                                                                  # [trace]
    write_buffers(trace_path, frame, depth, W, H, top_row_first=True)         # [trace]
    if textured:                                                               # [trace]
        write_ppm(texture_name, mips[0], tw, th)                              # [trace]
    return 0


if __name__ == "__main__":
    sys.exit(main())
