/* c_scanline.c: a float32 C99 scanline rasterizer, the way the textbook's chapter on polygon
 * filling teaches it: the corners sorted by y, the long edge and the two short ones walked row by
 * row, a span filled between them. Window coordinates y down (row 0 at the top); no sub-pixel
 * snapping (the trace has no `subpixel` line). Its own tie handling: rows from ceil(ytop - 0.5)
 * to ceil(ybottom - 0.5) - 1 and spans from ceil(xl - 0.5) to ceil(xr - 0.5) - 1, which is the
 * top-left rule. Full clipping against the six planes (carried over from the first assignment,
 * so its corners stay on the screen), culling by the winding on screen. z, q and every a·q are
 * interpolated along the edges and across the span, then a = (a·q)/q: perspective-correct
 * Gouraud, Phong and s t; textures nearest, bilinear and trilinear (its λ from the plane of s·q,
 * t·q and q, evaluated at the pixel's 2x2 quad).
 *
 *     c_scanline SCENE TRACE      (TRACE.ppm, TRACE.pfm and TRACE.texture.ppm beside it)
 *
 * Variants, each a bug students make:
 *   -DROUND_SPANS     span ends rounded: x from roundf(xl) while x < roundf(xr). It differs
 *                     from ceil(x - 0.5) only when a pixel centre lies exactly on the edge, which
 *                     makes it a top-right rule; without a `subpixel` line those pixels are no
 *                     facts to check, so check cannot see it anywhere: I predict agree.
 *   -DAFFINE_COLOUR   Gouraud's colours walked as they are, without q (colour_affine); seen only
 *                     where a big triangle recedes steeply (the floor, lit by a low light), not
 *                     on the cube or the knot (small triangles: within the allowance).
 *   -DNO_DEPTH_WRITE  the depth test made, the buffer never written (depth_not_written).
 *   -DSKIP_TINY       a rule of its own, "to go faster": a triangle under 1 pixel of area is not
 *                     filled (still written to the trace, as it was handed to the rasterizer):
 *                     holes in the small knot no catalogue mistake makes (unexplained).
 *
 * Lines ending in "[trace]" were added only to write the trace.
 *
 * expect square: agree
 * expect cube_flat: agree
 * expect cube_gouraud_ads: agree
 * expect knot_phong: agree
 * expect knot_gouraud_ad: agree
 * expect floor_gouraud: agree
 * expect floor_bilinear: agree
 * expect floor_trilinear: agree
 * expect square -DROUND_SPANS: agree
 * expect knot_phong -DROUND_SPANS: agree
 * expect floor_gouraud -DAFFINE_COLOUR: differs mistakes=colour_affine
 * expect knot_phong -DAFFINE_COLOUR: agree
 * expect cube_gouraud_ads -DNO_DEPTH_WRITE: differs mistakes=depth_not_written
 * expect knot_phong -DNO_DEPTH_WRITE: differs mistakes=depth_not_written
 * expect knot_flat -DSKIP_TINY: differs unexplained
 * expect square -DSKIP_TINY: agree
 * expect-grade: 200
 * expect-grade -DROUND_SPANS: 200
 * expect-grade -DAFFINE_COLOUR: gouraud=8 synchronized=13
 *   (predicted before grading: 200, on Gouraud scenes of small triangles; the rubric's Gouraud
 *   line has floor_gouraud too, whose large slanted triangles show affine colour: graded 181)
 * expect-grade -DNO_DEPTH_WRITE: zbuffer=0 resize=0 synchronized=0
 * expect-grade -DSKIP_TINY: coverage=16 zbuffer=20 gouraud=16 phong=12 resize=7 synchronized=11
 */
#define CLOSE2GL_FLOAT                   /* [trace] */
#define CLOSE2GL_TRACE_IMPLEMENTATION
#include "close2gl_trace.h"
#define CLOSE2GL_RASTER_IMPLEMENTATION   /* [trace] */
#include "close2gl_raster.h"             /* [trace] */
#include "rcommon.h"

#include <math.h>

enum { RGB = 0, EYE = 3, NRM = 6, UV = 9, NA = 11 };   /* a corner's attributes */

typedef struct { float x, y, z, q, a[NA]; } vert;     /* window x, y down, z, q = 1/w */
typedef struct { float c[4], a[NA]; } cvert;          /* clip coordinates and attributes */

static int W, H, shading, filter, textured;
static float color[3], light_eye[3];
static unsigned char *fb;
static float *zb;

typedef struct { int w, h; unsigned char *px; } level;
static level mip[20];
static int levels;

static float dotf(const float *a, const float *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* I = Ia ka + f_att Il (kd max(N.L, 0) + ks max(V.R, 0)^n) in eye space, times the colour. */
static void light(const float *eye, const float *normal, int specular, float out[3])
{
    float n[3], l[3], v[3], r[3], d, nl, vr, f, lit, len;
    int k;
    len = sqrtf(dotf(normal, normal));
    for (k = 0; k < 3; k++) n[k] = normal[k] / len, l[k] = light_eye[k] - eye[k], v[k] = -eye[k];
    d = sqrtf(dotf(l, l));
    for (k = 0; k < 3; k++) l[k] /= d;
    len = sqrtf(dotf(v, v));
    for (k = 0; k < 3; k++) v[k] /= len;
    nl = dotf(n, l);
    for (k = 0; k < 3; k++) r[k] = 2 * nl * n[k] - l[k];
    vr = dotf(v, r);
    f = 1 / (float)(RC_ATT[0] + RC_ATT[1] * d + RC_ATT[2] * d * d);
    if (f > 1) f = 1;
    lit = (float)RC_KD * (nl > 0 ? nl : 0);
    if (specular) lit += (float)RC_KS * powf(vr > 0 ? vr : 0, (float)RC_SHININESS);
    for (k = 0; k < 3; k++) out[k] = color[k] * (float)(RC_IA[k] * RC_KA + RC_IL[k] * f * lit);
}

/* ---- textures ---------------------------------------------------------------------------- */

static void make_mips(void)
{
    for (levels = 1; levels < 20 && (mip[levels - 1].w > 1 || mip[levels - 1].h > 1); levels++) {
        level a = mip[levels - 1], b;
        int x, y, c;
        b.w = a.w / 2 > 1 ? a.w / 2 : 1, b.h = a.h / 2 > 1 ? a.h / 2 : 1;
        b.px = (unsigned char *)malloc((size_t)b.w * b.h * 3);
        for (y = 0; y < b.h; y++)
            for (x = 0; x < b.w; x++)
                for (c = 0; c < 3; c++) {
                    int x1 = 2 * x + 1 < a.w ? 2 * x + 1 : a.w - 1, y1 = 2 * y + 1 < a.h ? 2 * y + 1 : a.h - 1;
                    int sum = a.px[(2 * y * a.w + 2 * x) * 3 + c] + a.px[(2 * y * a.w + x1) * 3 + c]
                              + a.px[(y1 * a.w + 2 * x) * 3 + c] + a.px[(y1 * a.w + x1) * 3 + c];
                    b.px[(y * b.w + x) * 3 + c] = (unsigned char)((sum + 2) / 4);
                }
        mip[levels] = b;
    }
}

static int wrapi(float f, int n)
{
    long k = (long)(f < -1e8f ? -1e8f : f > 1e8f ? 1e8f : f);
    return (int)(((k % n) + n) % n);
}

static void texel(int lv, float x, float y, float out[3])   /* x from the left, y from the top */
{
    const unsigned char *p = mip[lv].px + ((size_t)wrapi(y, mip[lv].h) * mip[lv].w + wrapi(x, mip[lv].w)) * 3;
    out[0] = p[0] / 255.0f, out[1] = p[1] / 255.0f, out[2] = p[2] / 255.0f;
}

static void bilinear(int lv, float s, float t, float out[3])
{
    float x = s * mip[lv].w - 0.5f, y = (1 - t) * mip[lv].h - 0.5f, x0 = floorf(x), y0 = floorf(y);
    float fx = x - x0, fy = y - y0, a[3], b[3], c[3], d[3];
    int k;
    texel(lv, x0, y0, a), texel(lv, x0 + 1, y0, b), texel(lv, x0, y0 + 1, c), texel(lv, x0 + 1, y0 + 1, d);
    for (k = 0; k < 3; k++)
        out[k] = (a[k] * (1 - fx) + b[k] * fx) * (1 - fy) + (c[k] * (1 - fx) + d[k] * fx) * fy;
}

/* The texel colour at (s, t); lod the level of detail (trilinear only). */
static void sample(float s, float t, float lod, float out[3])
{
    if (filter == C2G_FILTER_NEAREST) {
        texel(0, floorf(s * mip[0].w), floorf((1 - t) * mip[0].h), out);
    } else if (filter == C2G_FILTER_BILINEAR) {
        bilinear(0, s, t, out);
    } else {
        float lo[3], hi[3], f;
        int l0, l1, k;
        lod = lod < 0 ? 0 : lod > levels - 1 ? (float)(levels - 1) : lod;
        l0 = (int)floorf(lod), l1 = l0 + 1 < levels ? l0 + 1 : l0, f = lod - (float)l0;
        bilinear(l0, s, t, lo), bilinear(l1, s, t, hi);
        for (k = 0; k < 3; k++) out[k] = lo[k] * (1 - f) + hi[k] * f;
    }
}

/* ---- the scanline rasterizer ------------------------------------------------------------- */

/* What is walked: z, q, and a·q of each attribute (Gouraud's rgb as it is, with AFFINE_COLOUR). */
enum { WZ = 0, WQ = 1, WA = 2, NW = 2 + NA };

static void walk_values(const vert *v, float out[NW])
{
    int k;
    out[WZ] = v->z, out[WQ] = v->q;
    for (k = 0; k < NA; k++) out[WA + k] = v->a[k] * v->q;
#ifdef AFFINE_COLOUR
    for (k = RGB; k < RGB + 3; k++) out[WA + k] = v->a[k];   /* BUG: no 1/w for the colours */
#endif
}

static void lerpv(const float *a, const float *b, float t, float *out)
{
    int k;
    for (k = 0; k < NW; k++) out[k] = a[k] + (b[k] - a[k]) * t;
}

/* The plane of s·q, t·q and q over the screen: f(x, y) = f0 + fx (x - x0) + fy (y - y0). */
typedef struct { float x0, y0, f0[3], fx[3], fy[3]; } plane;

static void st_at(const plane *p, float x, float y, float st[2])
{
    float f[3];
    int k;
    for (k = 0; k < 3; k++) f[k] = p->f0[k] + p->fx[k] * (x - p->x0) + p->fy[k] * (y - p->y0);
    st[0] = f[0] / f[2], st[1] = f[1] / f[2];
}

static void shade(const float *w, const plane *pl, int x, int y, unsigned char *out)
{
    float a[NA], rgb[3];
    int k;
    for (k = 0; k < NA; k++) a[k] = w[WA + k] / w[WQ];
#ifdef AFFINE_COLOUR
    for (k = RGB; k < RGB + 3; k++) a[k] = w[WA + k];
#endif
    if (shading == C2G_SHADING_NONE) memcpy(rgb, color, sizeof rgb);
    else if (shading == C2G_SHADING_PHONG) light(a + EYE, a + NRM, 1, rgb);
    else memcpy(rgb, a + RGB, sizeof rgb);
    if (textured) {
        float tex[3], lod = 0;
        if (filter == C2G_FILTER_TRILINEAR) {
            float c0[2], c1[2], c2[2], ax, ay, dx, dy, rho, across, down;
            float qx = (float)(x & ~1) + 0.5f, qy = (float)(y & ~1) + 0.5f;
            st_at(pl, qx, qy, c0), st_at(pl, qx + 1, qy, c1), st_at(pl, qx, qy + 1, c2);
            ax = (c1[0] - c0[0]) * mip[0].w, ay = (c1[1] - c0[1]) * mip[0].h;
            dx = (c2[0] - c0[0]) * mip[0].w, dy = (c2[1] - c0[1]) * mip[0].h;
            across = sqrtf(ax * ax + ay * ay), down = sqrtf(dx * dx + dy * dy);
            rho = across > down ? across : down;
            lod = log2f(rho);
        }
        sample(a[UV], a[UV + 1], lod, tex);
        for (k = 0; k < 3; k++) rgb[k] *= tex[k];
    }
    for (k = 0; k < 3; k++) {
        float c = rgb[k] < 0 ? 0 : rgb[k] > 1 ? 1 : rgb[k];
        out[k] = (unsigned char)(c * 255 + 0.5f);
    }
}

static void fill_triangle(const vert *in)
{
    const vert *v[3] = {&in[0], &in[1], &in[2]}, *tmp;
    float w[3][NW], L[NW], R[NW], P[NW];
    plane pl;
    int j, jtop, jbottom, i, k;
    /* sort by y (down) */
    if (v[1]->y < v[0]->y) tmp = v[0], v[0] = v[1], v[1] = tmp;
    if (v[2]->y < v[1]->y) tmp = v[1], v[1] = v[2], v[2] = tmp;
    if (v[1]->y < v[0]->y) tmp = v[0], v[0] = v[1], v[1] = tmp;
    if (v[2]->y - v[0]->y <= 0) return;
#ifdef SKIP_TINY
    if (fabsf((v[1]->x - v[0]->x) * (v[2]->y - v[0]->y) - (v[2]->x - v[0]->x) * (v[1]->y - v[0]->y)) < 2)
        return;   /* BUG of its own: under 1 pixel of area, skipped */
#endif
    for (i = 0; i < 3; i++) walk_values(v[i], w[i]);
    {   /* the plane of s q, t q, q (for λ) */
        float e1x = v[1]->x - v[0]->x, e1y = v[1]->y - v[0]->y, e2x = v[2]->x - v[0]->x, e2y = v[2]->y - v[0]->y;
        float det = e1x * e2y - e2x * e1y;
        pl.x0 = v[0]->x, pl.y0 = v[0]->y;
        for (k = 0; k < 3; k++) {
            float f0 = k < 2 ? v[0]->a[UV + k] * v[0]->q : v[0]->q;
            float f1 = k < 2 ? v[1]->a[UV + k] * v[1]->q : v[1]->q;
            float f2 = k < 2 ? v[2]->a[UV + k] * v[2]->q : v[2]->q;
            pl.f0[k] = f0;
            pl.fx[k] = det != 0 ? ((f1 - f0) * e2y - (f2 - f0) * e1y) / det : 0;
            pl.fy[k] = det != 0 ? ((f2 - f0) * e1x - (f1 - f0) * e2x) / det : 0;
        }
    }
    jtop = (int)ceilf(v[0]->y - 0.5f), jbottom = (int)ceilf(v[2]->y - 0.5f) - 1;
    if (jtop < 0) jtop = 0;
    if (jbottom > H - 1) jbottom = H - 1;
    for (j = jtop; j <= jbottom; j++) {
        float yc = (float)j + 0.5f, xl, xr, t;
        int x, xs, xe;
        /* the long edge 0 -> 2, and the short edge the row crosses */
        t = (yc - v[0]->y) / (v[2]->y - v[0]->y);
        xl = v[0]->x + (v[2]->x - v[0]->x) * t;
        lerpv(w[0], w[2], t, L);
        if (yc < v[1]->y) {
            t = (yc - v[0]->y) / (v[1]->y - v[0]->y);
            xr = v[0]->x + (v[1]->x - v[0]->x) * t;
            lerpv(w[0], w[1], t, R);
        } else {
            t = (yc - v[1]->y) / (v[2]->y - v[1]->y);
            xr = v[1]->x + (v[2]->x - v[1]->x) * t;
            lerpv(w[1], w[2], t, R);
        }
        if (xr < xl) {
            float s = xl;
            xl = xr, xr = s;
            memcpy(P, L, sizeof P), memcpy(L, R, sizeof L), memcpy(R, P, sizeof R);
        }
#ifdef ROUND_SPANS
        xs = (int)roundf(xl), xe = (int)roundf(xr) - 1;   /* BUG: ends rounded */
#else
        xs = (int)ceilf(xl - 0.5f), xe = (int)ceilf(xr - 0.5f) - 1;
#endif
        if (xs < 0) xs = 0;
        if (xe > W - 1) xe = W - 1;
        for (x = xs; x <= xe; x++) {
            int at = j * W + x;
            float z;
            lerpv(L, R, ((float)x + 0.5f - xl) / (xr - xl), P);
            z = P[WZ];
            if (!(z < zb[at])) continue;
#ifndef NO_DEPTH_WRITE
            zb[at] = z;
#endif
            shade(P, &pl, x, j, fb + 3 * at);
        }
    }
}

/* ---- clipping (Sutherland-Hodgman against the six planes, in clip space) ------------------ */

static float dist(const cvert *p, int plane)
{
    float c = p->c[plane / 2];
    return p->c[3] + (plane % 2 ? -c : c);
}

static int clip(cvert *poly, int n)
{
    cvert in[12];
    int plane, i, m;
    for (plane = 0; plane < 6 && n >= 3; plane++) {
        memcpy(in, poly, (size_t)n * sizeof *in);
        for (m = 0, i = 0; i < n; i++) {
            const cvert *a = &in[i], *b = &in[(i + 1) % n];
            float da = dist(a, plane), db = dist(b, plane);
            if (da >= 0) poly[m++] = *a;
            if ((da >= 0) != (db >= 0) && m < 12) {
                float t = da / (da - db);
                int k;
                for (k = 0; k < 4; k++) poly[m].c[k] = a->c[k] + (b->c[k] - a->c[k]) * t;
                for (k = 0; k < NA; k++) poly[m].a[k] = a->a[k] + (b->a[k] - a->a[k]) * t;
                m++;
            }
        }
        n = m;
    }
    return n;
}

int main(int argc, char **argv)
{
    c2g_scene s;
    rc_mesh m;
    double Md[16], Pd[16];
    float M[16], P[16], bg[3];
    c2r_real Mw[16], ia[3], il[3], att[3];                             /* [trace] */
    char texname[1100];                                                /* [trace] */
    FILE *out;                                                         /* [trace] */
    int i, k, t, lit, gouraud, attributes;
    unsigned char clear[3];

    if (argc != 3) {
        fprintf(stderr, "usage: %s SCENE TRACE\n", argv[0]);
        return 2;
    }
    if (!c2g_read_scene(argv[1], &s) || !rc_load(s.model, &m)) return 1;
    rc_camera(&s, &m, Md, Pd);
    for (i = 0; i < 16; i++) M[i] = (float)Md[i], P[i] = (float)Pd[i];
    W = s.width, H = s.height, shading = s.shading, filter = s.filter;
    for (k = 0; k < 3; k++) {
        color[k] = (float)s.color[k], bg[k] = (float)s.background[k];
        light_eye[k] = M[4 * k] * (float)s.light[0] + M[4 * k + 1] * (float)s.light[1]
                       + M[4 * k + 2] * (float)s.light[2] + M[4 * k + 3];
        clear[k] = (unsigned char)(bg[k] * 255 + 0.5f);
    }
    lit = shading != C2G_SHADING_NONE;
    gouraud = shading == C2G_SHADING_GOURAUD_AD || shading == C2G_SHADING_GOURAUD_ADS;
    if (s.has_texture && m.textured) {
        if (!(mip[0].px = c2r_read_ppm(s.texture, &mip[0].w, &mip[0].h))) return 1;
        make_mips();
        textured = 1;
    }
    fb = (unsigned char *)malloc((size_t)W * H * 3);
    zb = (float *)malloc((size_t)W * H * sizeof *zb);
    if (!fb || !zb) return 1;
    for (i = 0; i < W * H; i++) memcpy(fb + 3 * i, clear, 3), zb[i] = 1;

    if (!(out = c2r_open(argv[2]))) return 1;                          /* [trace] */
    c2r_write_model(out, rc_base(s.model));                            /* [trace] */
    c2r_write_window(out, W, H);                                       /* [trace] */
    c2r_write_origin(out, C2R_ORIGIN_TOP_LEFT);                        /* [trace] */
    c2r_write_shading(out, shading);                                   /* [trace] */
    c2r_write_color(out, color);                                       /* [trace] */
    c2r_write_background(out, bg);                                     /* [trace] */
    if (lit) {                                                         /* [trace] */
        for (i = 0; i < 16; i++) Mw[i] = M[i];                         /* [trace] */
        for (k = 0; k < 3; k++)                                        /* [trace] */
            ia[k] = (float)RC_IA[k], il[k] = (float)RC_IL[k], att[k] = (float)RC_ATT[k]; /* [trace] */
        c2r_write_light(out, s.light);                                 /* [trace] */
        c2r_write_matrix(out, Mw);                                     /* [trace] */
        c2r_write_lighting(out, ia, il, (float)RC_KA, (float)RC_KD, (float)RC_KS, /* [trace] */
                           (float)RC_SHININESS, att);                  /* [trace] */
    }                                                                  /* [trace] */
    snprintf(texname, sizeof texname, "%s.texture.ppm", argv[2]);      /* [trace] */
    if (textured) c2r_write_texture(out, rc_base(texname), filter);    /* [trace] */
    c2r_write_buffer_names(out, argv[2]);                              /* [trace] */
    attributes = (gouraud ? C2R_RGB : 0) | (lit ? C2R_EYE | C2R_NORMAL : 0) | (textured ? C2R_UV : 0); /* [trace] */
    c2r_write_attributes(out, attributes);                             /* [trace] */

    for (t = 0; t < m.count; t++) {
        cvert poly[12];
        vert win[12];
        float area = 0;
        int n, c;
        for (c = 0; c < 3; c++) {
            float p[4], e[4], nrm[3];
            for (k = 0; k < 3; k++) p[k] = (float)m.tri[t].p[c][k];
            p[3] = 1;
            for (k = 0; k < 4; k++) e[k] = M[4 * k] * p[0] + M[4 * k + 1] * p[1] + M[4 * k + 2] * p[2] + M[4 * k + 3];
            for (k = 0; k < 3; k++)
                nrm[k] = M[4 * k] * (float)m.tri[t].n[c][0] + M[4 * k + 1] * (float)m.tri[t].n[c][1]
                         + M[4 * k + 2] * (float)m.tri[t].n[c][2];
            for (k = 0; k < 4; k++)
                poly[c].c[k] = P[4 * k] * e[0] + P[4 * k + 1] * e[1] + P[4 * k + 2] * e[2] + P[4 * k + 3] * e[3];
            memcpy(poly[c].a + EYE, e, 3 * sizeof(float));
            memcpy(poly[c].a + NRM, nrm, sizeof nrm);
            if (gouraud) light(e, nrm, shading == C2G_SHADING_GOURAUD_ADS, poly[c].a + RGB);
            else memcpy(poly[c].a + RGB, color, sizeof color);
            poly[c].a[UV] = (float)m.tri[t].uv[c][0], poly[c].a[UV + 1] = (float)m.tri[t].uv[c][1];
        }
        n = clip(poly, 3);
        if (n < 3) continue;
        for (c = 0; c < n; c++) {
            float q = 1 / poly[c].c[3];
            win[c].x = (poly[c].c[0] * q + 1) * (float)W / 2;
            win[c].y = (1 - poly[c].c[1] * q) * (float)H / 2;          /* row 0 at the top */
            win[c].z = poly[c].c[2] * q * 0.5f + 0.5f;
            win[c].q = q;
            memcpy(win[c].a, poly[c].a, sizeof win[c].a);
        }
        for (c = 0; c < n; c++)   /* y down: counter-clockwise on screen is a negative area */
            area += win[c].x * win[(c + 1) % n].y - win[(c + 1) % n].x * win[c].y;
        if ((s.culling == C2G_CULL_CCW && area >= 0) || (s.culling == C2G_CULL_CW && area <= 0)) continue;
        for (c = 1; c + 1 < n; c++) {
            vert tri[3];
            c2r_real nums[3 * 15], *p = nums;                         /* [trace] */
            int corner;
            tri[0] = win[0], tri[1] = win[c], tri[2] = win[c + 1];
            for (corner = 0; corner < 3; corner++) {                   /* [trace] */
                *p++ = tri[corner].x, *p++ = tri[corner].y, *p++ = tri[corner].z, *p++ = tri[corner].q; /* [trace] */
                if (gouraud) memcpy(p, tri[corner].a + RGB, 3 * sizeof *p), p += 3; /* [trace] */
                if (lit) memcpy(p, tri[corner].a + EYE, 6 * sizeof *p), p += 6; /* [trace] */
                if (textured) memcpy(p, tri[corner].a + UV, 2 * sizeof *p), p += 2; /* [trace] */
            }                                                          /* [trace] */
            c2r_write_tri(out, t, nums);                               /* [trace] */
            fill_triangle(tri);
        }
    }
    if (!c2r_close(out)) return 1;                                     /* [trace] */
    if (!c2r_write_buffers(argv[2], fb, zb, W, H, C2R_TOP_ROW_FIRST)) return 1; /* [trace] */
    if (textured && !c2r_write_ppm(texname, mip[0].px, mip[0].w, mip[0].h, C2R_TOP_ROW_FIRST)) /* [trace] */
        return 1;                                                      /* [trace] */
    return 0;
}
