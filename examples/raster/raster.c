/* raster.c: the Close2GL rasterizer assignment in one small C99 program. It draws the frame a
 * scene file asks for with its own rasterizer (edge functions on corners snapped to 1/256 pixel,
 * the top-left rule, a z-buffer, Gouraud or Phong shading, a texture sampled nearest, bilinear
 * or trilinear) and writes a raster trace with its two buffers beside it:
 *
 *     raster SCENE TRACE      writes TRACE, TRACE.ppm (colour), TRACE.pfm (depth) and, when it
 *                             sampled one, TRACE.texture.ppm (the texture as it read it)
 *
 * It rasterizes as close2gl's textbook rasterizer (plugins/raster/src/textbook/) does, to the
 * pixel. Compile-time switches (see README.md):
 *   -DMISTAKE_<ID>        one of the catalogued mistakes (docs/raster-trace-format.md)
 *   -DTIE_RULE_TOP_RIGHT, -DTIE_RULE_BOTTOM_LEFT, -DTIE_RULE_BOTTOM_RIGHT   another tie rule
 *   -DCONVERT_TRUNCATE    colours to 8 bits by truncation;  -DDEPTH_LEQUAL  the test "<="
 *   -DSUBPIXEL_BITS=B     snap to 1/2^B pixel (default 8)
 *   -DRASTER_FLOAT        compute in float, as a float32 program does
 */
#ifdef RASTER_FLOAT
#define CLOSE2GL_FLOAT
#endif
#define CLOSE2GL_TRACE_IMPLEMENTATION
#include "../trace/close2gl_trace.h"
#define CLOSE2GL_RASTER_IMPLEMENTATION
#include "close2gl_raster.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef c2g_real real;
#define PI 3.14159265358979323846
#ifdef RASTER_FLOAT
#define SQRT sqrtf
#define POW powf
#define FLOOR floorf
#define ROUND roundf
#define LOG2 log2f
#define FMAX fmaxf
#define FMIN fminf
#else
#define SQRT sqrt
#define POW pow
#define FLOOR floor
#define ROUND round
#define LOG2 log2
#define FMAX fmax
#define FMIN fmin
#endif
#ifndef SUBPIXEL_BITS
#define SUBPIXEL_BITS 8
#endif
#define STEPS (1LL << SUBPIXEL_BITS)   /* sub-pixel steps per pixel */

/* ---- vectors ------------------------------------------------------------------------------- */

typedef struct { real x, y, z; } vec3;
typedef struct { real x, y, z, w; } vec4;

static vec3 v3(real x, real y, real z) { vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static vec3 add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec3 sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec3 mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static vec3 scale(vec3 a, real s) { return v3(a.x * s, a.y * s, a.z * s); }
static real dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static vec3 normalize(vec3 a) { return scale(a, (real)(1 / sqrt(dot(a, a)))); }
static vec3 from_array(const real a[3]) { return v3(a[0], a[1], a[2]); }
static void to_array(vec3 a, real out[3]) { out[0] = a.x; out[1] = a.y; out[2] = a.z; }
/* a (1 - s) + b s, as glam's lerp. */
static vec3 lerp(vec3 a, vec3 b, real s) { return add(scale(a, 1 - s), scale(b, s)); }

/* 4x4 matrices are real[16], row by row. */
static vec4 mat_vec(const real m[16], vec4 p)
{
    vec4 r;
    r.x = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * p.w;
    r.y = m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7] * p.w;
    r.z = m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11] * p.w;
    r.w = m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15] * p.w;
    return r;
}
static vec4 v4(vec3 p, real w) { vec4 r; r.x = p.x; r.y = p.y; r.z = p.z; r.w = w; return r; }

/* ---- the model: positions, vertex normals, texture coordinates ------------------------------ */

typedef struct { vec3 p[3], n[3]; real uv[3][2]; } triangle;
typedef struct { triangle *tri; int count, capacity, textured; } mesh;

static int push_triangle(mesh *m, const triangle *t)
{
    if (m->count == m->capacity) {
        int capacity = m->capacity ? 2 * m->capacity : 64;
        triangle *grown = (triangle *)realloc(m->tri, (size_t)capacity * sizeof *grown);
        if (!grown) return 0;
        m->tri = grown, m->capacity = capacity;
    }
    m->tri[m->count++] = *t;
    return 1;
}

typedef struct {
    FILE *f;
    const char *path;
    int line, count;
    char text[4096], copy[4096], *field[24];
} reader;

static int next_line(reader *r)
{
    do {
        if (!fgets(r->text, sizeof r->text, r->f)) return 0;
        r->line++;
        r->text[strcspn(r->text, "\r\n")] = '\0';
        strcpy(r->copy, r->text);
        r->count = c2g_split(r->copy, r->field, 24);
    } while (r->count == 0);
    return 1;
}

static int bad(const reader *r, const char *what)
{
    fprintf(stderr, "%s:%d: expected %s, found '%s'\n", r->path, r->line, what,
            r->text + strspn(r->text, " \t"));
    return 0;
}

/* Fields from `first` on are `count` numbers, stored in out. */
static int numbers(const reader *r, int first, int count, real *out)
{
    int i;
    if (r->count != first + count) return 0;
    for (i = 0; i < count; i++)
        if (!c2g_parse_real(r->field[first + i], &out[i])) return 0;
    return 1;
}

/* The course's .in format: a header (materials, an optional `Texture = YES|NO`, a comment), then
 * v0 v1 v2 `x y z nx ny nz material [s t]` and `face normal` per triangle. */
static int load_in(reader *r, mesh *m)
{
    real x[9], materials = 0;
    int k, more, header = 0;
    triangle t;
    memset(&t, 0, sizeof t);
    while ((more = next_line(r)) && strcmp(r->field[0], "v0") != 0) {
        if (r->count == 4 && !strcmp(r->field[0], "Material") && numbers(r, 3, 1, x))
            materials = x[0];
        if (r->count == 3 && !strcmp(r->field[0], "Texture")) m->textured = !strcmp(r->field[2], "YES");
        if (++header > 8 + 4 * (int)materials) return bad(r, "'v0 x y z nx ny nz material'");
    }
    for (; more; more = next_line(r)) {
        for (k = 0; k < 3; k++) {
            char tag[3] = {'v', (char)('0' + k), '\0'};
            if ((k > 0 && !next_line(r)) || strcmp(r->field[0], tag) != 0
                || !numbers(r, 1, m->textured ? 9 : 7, x))
                return bad(r, m->textured ? "'vK x y z nx ny nz material s t'"
                                          : "'vK x y z nx ny nz material'");
            t.p[k] = v3(x[0], x[1], x[2]);
            t.n[k] = v3(x[3], x[4], x[5]);
            t.uv[k][0] = m->textured ? x[7] : 0, t.uv[k][1] = m->textured ? x[8] : 0;
        }
        if (!next_line(r) || r->count != 5 || strcmp(r->field[0], "face"))
            return bad(r, "'face normal nx ny nz'");
        if (!push_triangle(m, &t)) return bad(r, "memory for another triangle");
    }
    return 1;
}

/* Wavefront OBJ: v, vt, vn and f (v, v/vt, v//vn, v/vt/vn; negative indices); polygons as fans.
 * A corner without a normal takes the face's; the mesh is textured when every corner has vt. */
static int load_obj(reader *r, mesh *m)
{
    real *data[3] = {NULL, NULL, NULL}, x[4];      /* v (xyz), vt (st), vn (xyz) */
    int count[3] = {0, 0, 0}, cap[3] = {0, 0, 0}, ok = 0, i, k, c, textured = 1;
    static const int width[3] = {3, 2, 3};
    while (next_line(r)) {
        const char *key = r->field[0];
        int kind = !strcmp(key, "v") ? 0 : !strcmp(key, "vt") ? 1 : !strcmp(key, "vn") ? 2 : -1;
        if (kind >= 0) {
            if (!numbers(r, 1, width[kind], x) && !numbers(r, 1, width[kind] + 1, x)) {
                bad(r, kind == 1 ? "'vt s t'" : "'v x y z' or 'vn x y z'");
                goto done;
            }
            if (count[kind] == cap[kind]) {
                real *grown;
                cap[kind] = cap[kind] ? 2 * cap[kind] : 256;
                grown = (real *)realloc(data[kind], (size_t)cap[kind] * 3 * sizeof *grown);
                if (!grown) { bad(r, "memory for another vertex"); goto done; }
                data[kind] = grown;
            }
            memcpy(data[kind] + 3 * count[kind]++, x, 3 * sizeof *x);
        } else if (!strcmp(key, "f")) {
            int index[23][3], corners = r->count - 1;
            if (corners < 3 || corners > 23) { bad(r, "'f' with 3 to 23 corners"); goto done; }
            for (i = 0; i < corners; i++) {
                char *s = r->field[1 + i], *end = s;
                for (c = 0; c < 3; c++) {               /* v, vt, vn: 0 when absent */
                    long j = strtol(s, &end, 10);
                    index[i][c] = end == s ? 0 : (int)(j < 0 ? j + count[c] + 1 : j);
                    if (end != s && (index[i][c] < 1 || index[i][c] > count[c])) break;
                    if (*end != '/') break;
                    s = end + 1;
                }
                for (c++; c < 3; c++) index[i][c] = 0;
                if (index[i][0] < 1 || index[i][0] > count[0] || *end != '\0') {
                    bad(r, "'f' corners v, v/vt, v//vn or v/vt/vn, of vertices read so far");
                    goto done;
                }
                textured &= index[i][1] > 0;
            }
            for (k = 1; k + 1 < corners; k++) {
                int corner[3];
                triangle t;
                vec3 face;
                corner[0] = 0, corner[1] = k, corner[2] = k + 1;
                for (i = 0; i < 3; i++) {
                    const int *at = index[corner[i]];
                    t.p[i] = from_array(data[0] + 3 * (at[0] - 1));
                    t.n[i] = at[2] ? from_array(data[2] + 3 * (at[2] - 1)) : v3(0, 0, 0);
                    t.uv[i][0] = at[1] ? data[1][3 * (at[1] - 1)] : 0;
                    t.uv[i][1] = at[1] ? data[1][3 * (at[1] - 1) + 1] : 0;
                }
                face = normalize(cross(sub(t.p[1], t.p[0]), sub(t.p[2], t.p[0])));
                for (i = 0; i < 3; i++)
                    if (!index[corner[i]][2]) t.n[i] = face;
                if (!push_triangle(m, &t)) { bad(r, "memory for another triangle"); goto done; }
            }
        }
    }
    m->textured = textured && m->count > 0;
    ok = 1;
done:
    for (i = 0; i < 3; i++) free(data[i]);
    return ok;
}

static int load_model(const char *path, mesh *m)
{
    reader r;
    size_t len = strlen(path);
    int ok;
    memset(&r, 0, sizeof r);
    memset(m, 0, sizeof *m);
    r.path = path;
    if (!(r.f = fopen(path, "rb"))) {
        perror(path);
        return 0;
    }
    ok = len > 4 && (!strcmp(path + len - 4, ".obj") || !strcmp(path + len - 4, ".OBJ"))
             ? load_obj(&r, m) : load_in(&r, m);
    fclose(r.f);
    if (ok && m->count == 0) {
        fprintf(stderr, "%s: expected at least one triangle, found none\n", path);
        ok = 0;
    }
    if (!ok) free(m->tri);
    return ok;
}

/* ---- the camera and M, P (as pipeline.c, without its mistakes) ------------------------------ */

typedef struct { vec3 c, u, v, n; real hfov, vfov, znear, zfar; } camera;

static void bounding_sphere(const mesh *m, vec3 *centre, real *radius)
{
    vec3 lo = m->tri[0].p[0], hi = lo;
    int i, k;
    for (i = 0; i < m->count; i++)
        for (k = 0; k < 3; k++) {
            vec3 p = m->tri[i].p[k];
            lo = v3(p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y, p.z < lo.z ? p.z : lo.z);
            hi = v3(p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y, p.z > hi.z ? p.z : hi.z);
        }
    *centre = scale(add(lo, hi), (real)0.5);
    *radius = (real)(0.5 * sqrt(dot(sub(hi, lo), sub(hi, lo))));
}

static camera frame(const mesh *m, const c2g_scene *s)
{
    vec3 centre;
    real r, d;
    camera cam;
    bounding_sphere(m, &centre, &r);
    if (!(r > 0)) r = 1;
    cam.hfov = s->hfov, cam.vfov = s->vfov;
    d = (real)(r / sin((s->hfov < s->vfov ? s->hfov : s->vfov) * PI / 360));
    cam.c = add(centre, v3(0, 0, d));
    cam.v = v3(0, 1, 0), cam.n = v3(0, 0, 1), cam.u = cross(cam.v, cam.n);
    cam.znear = s->has_near ? s->znear : (real)(0.5 * (d - r));
    if (!(cam.znear > 0)) cam.znear = (real)(0.01 * r);
    cam.zfar = s->has_far ? s->zfar : d + 2 * r;
    if (cam.zfar <= cam.znear) {
        if (s->has_near) cam.zfar = cam.znear + 2 * r;
        else cam.znear = (real)(0.01 * cam.zfar);
    }
    return cam;
}

static void apply_motion(camera *cam, const c2g_motion *m, vec3 lookat)
{
    vec3 u = cam->u, v = cam->v, n = cam->n;
    vec3 *axis = m->axis == 'u' ? &cam->u : m->axis == 'v' ? &cam->v : &cam->n;
    real angle = (real)(m->amount * PI / 180), cs = (real)cos(angle), sn = (real)sin(angle);
    if (m->kind == 'm') {
        cam->c = add(cam->c, scale(*axis, m->amount));
    } else if (m->kind == 'r') {
        if (m->axis == 'u') cam->v = add(scale(v, cs), scale(n, sn)), cam->n = sub(scale(n, cs), scale(v, sn));
        else if (m->axis == 'v') cam->n = add(scale(n, cs), scale(u, sn)), cam->u = sub(scale(u, cs), scale(n, sn));
        else cam->u = add(scale(u, cs), scale(v, sn)), cam->v = sub(scale(v, cs), scale(u, sn));
    } else {
        cam->c = add(cam->c, scale(*axis, m->amount));
        cam->n = normalize(sub(cam->c, lookat));
        if (m->axis == 'u') cam->u = normalize(cross(cam->v, cam->n)), cam->v = cross(cam->n, cam->u);
        else cam->v = normalize(cross(cam->n, cam->u)), cam->u = cross(cam->v, cam->n);
    }
}

static void modelview(const camera *cam, real M[16])
{
    vec3 r[3];
    int i;
    r[0] = cam->u, r[1] = cam->v, r[2] = cam->n;
    for (i = 0; i < 3; i++) {
        M[4 * i] = r[i].x, M[4 * i + 1] = r[i].y, M[4 * i + 2] = r[i].z;
        M[4 * i + 3] = -dot(cam->c, r[i]);
    }
    M[12] = M[13] = M[14] = 0, M[15] = 1;
}

static void projection(const camera *cam, real P[16])
{
    real n = cam->znear, f = cam->zfar;
    real t = (real)(n * tan(cam->vfov * PI / 360)), r = (real)(n * tan(cam->hfov * PI / 360));
    int i;
    for (i = 0; i < 16; i++) P[i] = 0;
    P[0] = n / r, P[5] = n / t;
    P[10] = -(f + n) / (f - n), P[11] = -2 * f * n / (f - n), P[14] = -1;
}

/* ---- lighting (the lecture's: Lighting::default) -------------------------------------------- */

enum { RGB = 0, EYE = 3, NORMAL = 6, UV = 9, ATTRIBUTES = 11 };

static const real IA[3] = {(real)0.3, 1, (real)0.3}, IL[3] = {1, 1, 1};
static const real KA = (real)0.3, KD = (real)0.8, KS = (real)0.5, SHININESS = 10;
static const real ATTENUATION[3] = {(real)0.01, (real)0.001, 0};

static vec3 light_eye;   /* the light in eye space: M·light */

/* Normalised without a NaN for a zero vector. */
static vec3 unit(vec3 v)
{
    real s = SQRT(FMAX(dot(v, v), (real)1e-30));
    return v3(v.x / s, v.y / s, v.z / s);
}

/* I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n) in eye space; specular 0: no ks term.
 * at_pixel: Phong's interpolated normal (the one MISTAKE_NORMAL_NOT_RENORMALIZED leaves as is). */
static vec3 illumination(vec3 eye, vec3 normal, int specular, int at_pixel)
{
    vec3 n = unit(normal), to_light = sub(light_eye, eye), l = unit(to_light);
    vec3 v = unit(scale(eye, -1)), r, out;
    real ks = specular ? KS : 0, diffuse, shine, d, f_att, lit;
    (void)at_pixel;
#ifdef MISTAKE_NORMAL_NOT_RENORMALIZED
    if (at_pixel) n = normal;                      /* MISTAKE: |N| < 1 between the corners */
#endif
#ifdef MISTAKE_NO_SPECULAR
    ks = 0;                                        /* MISTAKE: ADS without S */
#endif
#ifdef MISTAKE_VIEWER_AT_INFINITY
    v = v3(0, 0, 1);                               /* MISTAKE: V the same everywhere */
#endif
    r = sub(scale(n, 2 * dot(n, l)), l);
    diffuse = KD * FMAX(dot(n, l), 0);
#ifdef MISTAKE_DIFFUSE_UNCLAMPED
    diffuse = KD * dot(n, l);                      /* MISTAKE: no max(N·L, 0) */
#endif
    shine = FMAX(dot(v, r), 0);
#ifdef MISTAKE_SPECULAR_UNCLAMPED
    shine = dot(v, r);                             /* MISTAKE: no max(V·R, 0) */
#endif
#ifdef MISTAKE_BLINN_PHONG
    shine = FMAX(dot(n, unit(add(l, v))), 0);      /* MISTAKE: N·H in place of V·R */
#endif
    d = SQRT(dot(to_light, to_light));
    f_att = FMIN(1 / (ATTENUATION[0] + ATTENUATION[1] * d + ATTENUATION[2] * d * d), 1);
#ifdef MISTAKE_NO_ATTENUATION
    f_att = 1;                                     /* MISTAKE: f_att = 1 */
#endif
    lit = diffuse + ks * POW(shine, SHININESS);
    out = v3(IA[0] * KA + IL[0] * f_att * lit, IA[1] * KA + IL[1] * f_att * lit,
             IA[2] * KA + IL[2] * f_att * lit);
    return out;
}

/* ---- the texture: its mipmap chain (texture.rs's mip_chain and half) ------------------------- */

typedef struct { int w, h; unsigned char *rgb; } image;
static image levels[32];
static int level_count;

static void mip_chain(image base)
{
    levels[0] = base;
    for (level_count = 1; levels[level_count - 1].w > 1 || levels[level_count - 1].h > 1;
         level_count++) {
        image a = levels[level_count - 1], b;
        int x, y, c;
        b.w = a.w / 2 > 1 ? a.w / 2 : 1, b.h = a.h / 2 > 1 ? a.h / 2 : 1;
        b.rgb = (unsigned char *)malloc((size_t)b.w * b.h * 3);
        for (y = 0; b.rgb && y < b.h; y++)
            for (x = 0; x < b.w; x++)
                for (c = 0; c < 3; c++) {
                    int x0 = 2 * x, x1 = 2 * x + 1 < a.w ? 2 * x + 1 : a.w - 1;
                    int y0 = 2 * y, y1 = 2 * y + 1 < a.h ? 2 * y + 1 : a.h - 1;
                    int sum = a.rgb[(y0 * a.w + x0) * 3 + c] + a.rgb[(y0 * a.w + x1) * 3 + c]
                              + a.rgb[(y1 * a.w + x0) * 3 + c] + a.rgb[(y1 * a.w + x1) * 3 + c];
                    b.rgb[(y * b.w + x) * 3 + c] = (unsigned char)((sum + 2) / 4);
                }
        if (!b.rgb) break;
        levels[level_count] = b;
    }
}

/* Index i (a whole number) wrapped into 0..n-1 (GL_REPEAT). */
static int wrap(real i, int n)
{
    long long k;
    if (i != i) return 0;                          /* NaN */
    k = (long long)(i < -1e9 ? -1e9 : i > 1e9 ? 1e9 : i);
#ifdef MISTAKE_CLAMP_NOT_REPEAT
    return k < 0 ? 0 : k >= n ? n - 1 : (int)k;    /* MISTAKE: the edge texels, not repeat */
#endif
    return (int)(((k % n) + n) % n);
}

/* Texel (x, y) of a level, x from the left, y from the top, in 0..1. */
static vec3 texel(int level, real x, real y)
{
    const image *im = &levels[level];
    const unsigned char *p = im->rgb + ((size_t)wrap(y, im->h) * im->w + wrap(x, im->w)) * 3;
    return v3((real)p[0] / 255, (real)p[1] / 255, (real)p[2] / 255);
}

/* Where (s, t) falls in a level, in texels from its top-left corner (t grows upwards). */
static void position(int level, const real st[2], real p[2])
{
    p[0] = st[0] * (real)levels[level].w;
    p[1] = (1 - st[1]) * (real)levels[level].h;
#ifdef MISTAKE_T_NOT_FLIPPED
    p[1] = st[1] * (real)levels[level].h;          /* MISTAKE: t = 0 is the top row */
#endif
}

static vec3 nearest(const real st[2])
{
    real p[2];
    position(0, st, p);
#ifdef MISTAKE_NEAREST_ROUNDS
    return texel(0, ROUND(p[0]), ROUND(p[1]));     /* MISTAKE: round(s W), not floor */
#endif
    return texel(0, FLOOR(p[0]), FLOOR(p[1]));
}

static vec3 bilinear(int level, const real st[2])
{
    real p[2], cx, cy, fx, fy;
    position(level, st, p);
#ifndef MISTAKE_BILINEAR_NO_HALF_TEXEL
    p[0] -= (real)0.5, p[1] -= (real)0.5;          /* (without: MISTAKE, half a texel off) */
#endif
    cx = FLOOR(p[0]), cy = FLOOR(p[1]), fx = p[0] - cx, fy = p[1] - cy;
    return lerp(lerp(texel(level, cx, cy), texel(level, cx + 1, cy), fx),
                lerp(texel(level, cx, cy + 1), texel(level, cx + 1, cy + 1), fx), fy);
}

static vec3 trilinear(const real st[2], real lod)
{
    real top = (real)(level_count - 1), below;
    lod = FMIN(FMAX(lod, 0), top);
#ifdef MISTAKE_MIP_NEAREST_LEVEL
    return bilinear((int)ROUND(lod), st);          /* MISTAKE: one level, no blend */
#endif
    below = FLOOR(lod);
    return lerp(bilinear((int)below, st), bilinear((int)FMIN(below + 1, top), st), lod - below);
}

/* ---- the rasterizer (textbook/) ----------------------------------------------------------- */

/* A corner: window x, y (y up, as the trace gives it), depth, 1/w, and its attributes. */
typedef struct { real win[4]; real a[ATTRIBUTES]; } corner;

/* What setup makes of a corner: x, y down from the top (the textbook's rows), snapped. */
typedef struct { double x, y; long long s[2]; const corner *c; } vertex;

static int W, H, shading, sampled, filter;
static vec3 color;
static unsigned char *framebuffer;
static float *depthbuffer;

/* Twice the signed area of (a, b, p): positive when p is left of a -> b as y grows downwards. */
static long long edge_i(const long long a[2], const long long b[2], const long long p[2])
{
    return (b[1] - a[1]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[1] - a[1]);
}
static double edge_d(const double a[2], const double b[2], const double p[2])
{
    return (b[1] - a[1]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[1] - a[1]);
}

/* Whether a centre exactly on edge a -> b (y down, the triangle wound as draw_triangle winds
 * it) is inside: the top-left rule, or another legal one. */
static int tie(const long long a[2], const long long b[2])
{
#if defined(TIE_RULE_TOP_RIGHT)
    return a[1] > b[1] || (a[1] == b[1] && a[0] > b[0]);
#elif defined(TIE_RULE_BOTTOM_LEFT)
    return a[1] < b[1] || (a[1] == b[1] && a[0] < b[0]);
#elif defined(TIE_RULE_BOTTOM_RIGHT)
    return a[1] > b[1] || (a[1] == b[1] && a[0] < b[0]);
#else
    return a[1] < b[1] || (a[1] == b[1] && a[0] > b[0]);  /* a left edge, or a top one */
#endif
}

static int covers(const vertex v[3], const long long centre[2])
{
    int i;
    for (i = 0; i < 3; i++) {
        long long f = edge_i(v[i].s, v[(i + 1) % 3].s, centre);
        (void)tie;
#if defined(MISTAKE_FILL_RULE_INCLUSIVE)
        if (f < 0) return 0;                       /* MISTAKE: on an edge is inside */
#elif defined(MISTAKE_FILL_RULE_EXCLUSIVE)
        if (f <= 0) return 0;                      /* MISTAKE: on an edge is outside */
#else
        if (f < 0 || (f == 0 && !tie(v[i].s, v[(i + 1) % 3].s))) return 0;
#endif
    }
    return 1;
}

/* Pixel (x, y) (y down)'s sample: its centre as a snapped point and as a window point. */
static void sample(long long x, long long y, long long centre[2], double p[2])
{
    centre[0] = x * STEPS, centre[1] = y * STEPS;
    p[0] = (double)x + 0.5, p[1] = (double)y + 0.5;
#ifdef MISTAKE_PIXEL_CORNER_SAMPLES
    /* MISTAKE: the corner (i, j) of the trace's pixel (y up: its lower-left corner) */
    centre[0] -= STEPS / 2, centre[1] += STEPS / 2;
    p[0] = (double)x, p[1] = (double)y + 1;
#endif
}

/* The barycentric weights of window point p, from the unsnapped corners, in double. */
static void barycentrics(const vertex v[3], const double p[2], double w[3])
{
    double a[2], b[2], c[2], area;
    a[0] = v[0].x, a[1] = v[0].y, b[0] = v[1].x, b[1] = v[1].y, c[0] = v[2].x, c[1] = v[2].y;
    area = edge_d(a, b, c);
    w[0] = edge_d(b, c, p) / area, w[1] = edge_d(c, a, p) / area, w[2] = edge_d(a, b, p) / area;
}

/* The attributes at window point p: perspective-correct (a·q and q blended, then divided). v is
 * as draw_triangle wound it, trace the corners in the tri line's order, o[k] v[k]'s place there. */
static void varyings(const vertex v[3], const corner *trace, const int o[3], const double p[2],
                     real out[ATTRIBUTES])
{
    double w[3];
    const corner *c[3];
    int k, i;
    barycentrics(v, p, w);
    for (k = 0; k < 3; k++) c[k] = &trace[o[k]];
#ifdef MISTAKE_WEIGHTS_ROTATED
    for (k = 0; k < 3; k++) c[k] = &trace[(o[k] + 1) % 3];  /* MISTAKE: the next corner's values */
#endif
    for (i = 0; i < ATTRIBUTES; i++) {
        double over_w[3], sum = 0, blend = 0;
        int affine = 0;
#ifdef MISTAKE_COLOUR_AFFINE
        affine |= i < EYE;                         /* MISTAKE: Gouraud's colours without 1/w */
#endif
#ifdef MISTAKE_PHONG_AFFINE
        affine |= i >= EYE && i < UV;              /* MISTAKE: eye and normal without 1/w */
#endif
#ifdef MISTAKE_UV_AFFINE
        affine |= i >= UV;                         /* MISTAKE: s, t without 1/w */
#endif
        for (k = 0; k < 3; k++) over_w[k] = affine ? w[k] : w[k] * (double)c[k]->win[3];
        for (k = 0; k < 3; k++) sum += over_w[k];
        for (k = 0; k < 3; k++) blend += over_w[k] * (double)c[k]->a[i];
        out[i] = (real)(affine ? blend : blend / sum);
#ifdef MISTAKE_NO_INTERPOLATION
        out[i] = trace[0].a[i];                    /* MISTAKE: the first corner's values */
#endif
    }
}

/* A colour in 0..1 as 8 bits: clamped, rounded to nearest. */
static unsigned char byte(real c)
{
#ifdef MISTAKE_COLOUR_NOT_CLAMPED
    real x = c * 255 + (real)0.5;                  /* MISTAKE: no clamp; the byte wraps */
    return (unsigned char)(x == x && x > -1e9 && x < 1e9 ? (long long)x & 255 : 0);
#endif
    if (c != c) return 0;
    c = c < 0 ? 0 : c > 1 ? 1 : c;
#ifdef CONVERT_TRUNCATE
    return (unsigned char)(c * 255);
#endif
    return (unsigned char)(c * 255 + (real)0.5);
}

/* The colour of pixel (x, y) of the triangle. */
static vec3 colour(const vertex v[3], const corner *trace, const int o[3], long long x,
                   long long y)
{
    real here[ATTRIBUTES], st[2], at[ATTRIBUTES];
    long long centre[2];
    double p[2];
    vec3 rgb, texel_rgb;
    sample(x, y, centre, p);
    varyings(v, trace, o, p, here);
    if (shading == C2G_SHADING_NONE) rgb = color;
    else if (shading == C2G_SHADING_PHONG)
        rgb = mul(color, illumination(from_array(here + EYE), from_array(here + NORMAL), 1, 1));
    else rgb = from_array(here + RGB);             /* Gouraud: the corners' lit colours */
    if (!sampled) return rgb;
    st[0] = here[UV], st[1] = here[UV + 1];
    if (filter == C2G_FILTER_NEAREST) texel_rgb = nearest(st);
    else if (filter == C2G_FILTER_BILINEAR) texel_rgb = bilinear(0, st);
    else {
        /* λ: log2 of the longer step of (s, t) across and down the pixel's 2x2 quad, in texels. */
        real corner_st[2], across[2], down[2], size[2], rho;
        long long left = x & ~1LL, top = y & ~1LL;
        int k;
        size[0] = (real)levels[0].w, size[1] = (real)levels[0].h;
#ifdef MISTAKE_LOD_UNSCALED
        size[0] = size[1] = 1;                     /* MISTAKE: in texture coordinates */
#endif
        sample(left, top, centre, p), varyings(v, trace, o, p, at);
        corner_st[0] = at[UV], corner_st[1] = at[UV + 1];
        sample(left + 1, top, centre, p), varyings(v, trace, o, p, at);
        for (k = 0; k < 2; k++) across[k] = (at[UV + k] - corner_st[k]) * size[k];
        sample(left, top + 1, centre, p), varyings(v, trace, o, p, at);
        for (k = 0; k < 2; k++) down[k] = (at[UV + k] - corner_st[k]) * size[k];
        rho = FMAX(SQRT(across[0] * across[0] + across[1] * across[1]),
                   SQRT(down[0] * down[0] + down[1] * down[1]));
#ifdef MISTAKE_LOD_ONE_AXIS
        rho = SQRT(across[0] * across[0] + across[1] * across[1]);  /* MISTAKE: across only */
#endif
#ifdef MISTAKE_LOD_ABSOLUTE
        texel_rgb = trilinear(st, (real)fabs(LOG2(rho)));  /* MISTAKE: |λ| */
#else
        texel_rgb = trilinear(st, LOG2(rho));
#endif
    }
#ifdef MISTAKE_NO_WRAP_BLACK
    if (!(st[0] >= 0 && st[0] <= 1 && st[1] >= 0 && st[1] <= 1))
        texel_rgb = v3(0, 0, 0);                   /* MISTAKE: outside [0, 1] is black */
#endif
    return mul(rgb, texel_rgb);
}

/* One triangle (corners in the tri line's order), pixel by pixel over its bounding box. */
static void draw_triangle(const corner trace[3])
{
    vertex v[3], swap;
    int o[3] = {0, 1, 2}, i;
    long long area, lo[2], hi[2], x, y;
    double box[4] = {1e300, -1e300, 1e300, -1e300};   /* the trace's x, y extent */
    for (i = 0; i < 3; i++) {
        real wx = trace[i].win[0], wy = trace[i].win[1];
#ifdef MISTAKE_VERTICES_ROUNDED
        wx = ROUND(wx), wy = ROUND(wy);            /* MISTAKE: whole pixels (trace's y up) */
#endif
#ifdef MISTAKE_VERTICES_TRUNCATED
        wx = (real)(long long)wx, wy = (real)(long long)wy;  /* MISTAKE: cast to int */
#endif
        v[i].c = &trace[i];
        v[i].x = (double)wx, v[i].y = (double)H - (double)wy;  /* y down, as the textbook */
        if (!(fabs(v[i].x) <= 2097152 && fabs(v[i].y) <= 2097152) || trace[i].win[2] != trace[i].win[2]
            || !(fabs((double)trace[i].win[3]) < 1e300))
            return;                                 /* not finite, or too far: not drawn */
        v[i].s[0] = llrint((v[i].x - 0.5) * STEPS);  /* to nearest, ties to even */
        v[i].s[1] = llrint((v[i].y - 0.5) * STEPS);
        box[0] = fmin(box[0], (double)trace[i].win[0]), box[1] = fmax(box[1], (double)trace[i].win[0]);
        box[2] = fmin(box[2], (double)trace[i].win[1]), box[3] = fmax(box[3], (double)trace[i].win[1]);
    }
    area = edge_i(v[0].s, v[1].s, v[2].s);
    if (area == 0) return;
    if (area < 0) swap = v[1], v[1] = v[2], v[2] = swap, o[1] = 2, o[2] = 1;
    for (i = 0; i < 2; i++) {
        long long mn = v[0].s[i], mx = v[0].s[i];
        int k;
        for (k = 1; k < 3; k++) mn = v[k].s[i] < mn ? v[k].s[i] : mn, mx = v[k].s[i] > mx ? v[k].s[i] : mx;
        lo[i] = mn / STEPS - 1 > 0 ? mn / STEPS - 1 : 0;
        hi[i] = mx / STEPS + 1 < (i ? H : W) - 1 ? mx / STEPS + 1 : (i ? H : W) - 1;
    }
    for (y = lo[1]; y <= hi[1]; y++)
        for (x = lo[0]; x <= hi[0]; x++) {
            long long centre[2], at = y * W + x, j = H - 1 - y;  /* j: the trace's row, y up */
            double p[2], w[3], z;
            float depth;
            int pass;
            vec3 rgb;
            (void)j;
            sample(x, y, centre, p);
            if (!covers(v, centre)) continue;
#ifdef MISTAKE_BOUNDING_BOX_SHORT
            if (!(x >= (long long)floor(box[0]) && x < (long long)floor(box[1])
                  && j >= (long long)floor(box[2]) && j < (long long)floor(box[3])))
                continue;                          /* MISTAKE: the box's last column and row */
#endif
#ifdef MISTAKE_VIEWPORT_EDGE_SKIPPED
            if (x == W - 1 || j == H - 1) continue; /* MISTAKE: the window's last column, row */
#endif
            barycentrics(v, p, w);
            z = w[0] * (double)v[0].c->win[2] + w[1] * (double)v[1].c->win[2]
                + w[2] * (double)v[2].c->win[2];
#ifdef MISTAKE_DEPTH_PERSPECTIVE
            {   /* MISTAKE: depth as a varying: z·q and q blended, then divided */
                double q[3];
                for (i = 0; i < 3; i++) q[i] = w[i] * (double)v[i].c->win[3];
                z = (q[0] * (double)v[0].c->win[2] + q[1] * (double)v[1].c->win[2]
                     + q[2] * (double)v[2].c->win[2]) / (q[0] + q[1] + q[2]);
            }
#endif
#ifdef MISTAKE_DEPTH_NDC
            z = w[0] * (2 * (double)v[0].c->win[2] - 1) + w[1] * (2 * (double)v[1].c->win[2] - 1)
                + w[2] * (2 * (double)v[2].c->win[2] - 1);  /* MISTAKE: NDC z, not mapped */
#endif
            depth = (float)z;
#if defined(MISTAKE_NO_DEPTH_TEST)
            pass = 1;                              /* MISTAKE: every fragment */
#elif defined(MISTAKE_FARTHEST_WINS)
            pass = depth > depthbuffer[at];        /* MISTAKE: greater (cleared to 0) */
#elif defined(DEPTH_LEQUAL)
            pass = depth <= depthbuffer[at];
#else
            pass = depth < depthbuffer[at];
#endif
            if (!pass) continue;
#ifndef MISTAKE_DEPTH_NOT_WRITTEN
            depthbuffer[at] = depth;               /* (not written: MISTAKE) */
#endif
            rgb = colour(v, trace, o, x, y);
            framebuffer[3 * at] = byte(rgb.x);
            framebuffer[3 * at + 1] = byte(rgb.y);
            framebuffer[3 * at + 2] = byte(rgb.z);
        }
}

/* ---- clipping (Sutherland-Hodgman in clip space, attributes blended linearly) --------------- */

typedef struct { vec4 p; real a[ATTRIBUTES]; } clip_vertex;

static real plane_distance(vec4 p, int i)
{
    real coordinate = i < 2 ? p.x : i < 4 ? p.y : p.z;
    return p.w + (i % 2 ? -coordinate : coordinate);
}

static int inside(vec4 p, int i) { return plane_distance(p, i) >= 0 && (i != 4 || p.w > 0); }

/* Where the edge from `in` (inside) to `out` crosses plane i; every attribute blended alike. */
static clip_vertex crossing(const clip_vertex *in, const clip_vertex *out, int i)
{
    real din = plane_distance(in->p, i), dout = plane_distance(out->p, i), t = din / (din - dout);
    clip_vertex c;
    int k;
    c.p.x = in->p.x + t * (out->p.x - in->p.x), c.p.y = in->p.y + t * (out->p.y - in->p.y);
    c.p.z = in->p.z + t * (out->p.z - in->p.z), c.p.w = in->p.w + t * (out->p.w - in->p.w);
    for (k = 0; k < ATTRIBUTES; k++) c.a[k] = in->a[k] + t * (out->a[k] - in->a[k]);
    return c;
}

/* Against x >= -w, x <= w, y >= -w, y <= w, z >= -w, z <= w; poly has room for 9 corners. */
static int clip_polygon(clip_vertex poly[9], int k)
{
    clip_vertex in[9];
    int i, j, kin, any;
    for (i = 0; i < 6 && k >= 3; i++) {
        for (any = 0, j = 0; j < k; j++) any |= !inside(poly[j].p, i);
        if (!any) continue;
        if (i == 4)
            for (j = 0; j < k; j++)
                if (poly[j].p.w <= 0 && plane_distance(poly[j].p, 4) >= 0) return 0;
        memcpy(in, poly, (size_t)k * sizeof *in);
        for (kin = k, k = 0, j = 0; j < kin; j++) {
            const clip_vertex *a = &in[j], *b = &in[(j + 1) % kin];
            int ia = inside(a->p, i), ib = inside(b->p, i);
            if (ia) poly[k++] = *a;
            if (ia && !ib && plane_distance(a->p, i) > 0) poly[k++] = crossing(a, b, i);
            if (!ia && ib && plane_distance(b->p, i) > 0) poly[k++] = crossing(b, a, i);
        }
    }
    return k;
}

/* ---- the frame ----------------------------------------------------------------------------- */

/* PATH's file name (the trace names its buffers relative to its own folder). */
static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

int main(int argc, char **argv)
{
    c2g_scene s;
    mesh m;
    camera cam;
    vec3 lookat;
    real M[16], P[16], radius, background[3];
    char *texture_name;
    FILE *out;
    int i, t, lit, attributes, per_corner, order = C2R_TOP_ROW_FIRST;
    size_t pixels;
    unsigned char clear[3];

    if (argc != 3) {
        fprintf(stderr, "usage: %s SCENE TRACE\n", argv[0]);
        return 2;
    }
    if (!c2g_read_scene(argv[1], &s) || !load_model(s.model, &m)) return 1;

    if (s.framed) {
        cam = frame(&m, &s);
    } else {
        cam.c = from_array(s.position), cam.u = from_array(s.u), cam.v = from_array(s.v);
        cam.n = from_array(s.n);
        cam.hfov = s.hfov, cam.vfov = s.vfov, cam.znear = s.znear, cam.zfar = s.zfar;
    }
    if (s.has_lookat) lookat = from_array(s.lookat);
    else bounding_sphere(&m, &lookat, &radius);
    for (i = 0; i < s.motion_count; i++) apply_motion(&cam, &s.motions[i], lookat);
    modelview(&cam, M);
    projection(&cam, P);
    {
        vec4 l = mat_vec(M, v4(from_array(s.light), 1));
        light_eye = v3(l.x, l.y, l.z);
#ifdef MISTAKE_LIGHT_IN_WORLD
        light_eye = from_array(s.light);           /* MISTAKE: M not applied */
#endif
    }

    /* The settings: a texture is sampled when the scene gives one and the model has s, t. */
    W = s.width, H = s.height, shading = s.shading, filter = s.filter;
    color = from_array(s.color);
    lit = shading != C2G_SHADING_NONE;
    if (s.has_texture && m.textured) {
        image base;
        if (!(base.rgb = c2r_read_ppm(s.texture, &base.w, &base.h))) return 1;
        mip_chain(base);
        sampled = 1;
    }
    attributes = (shading == C2G_SHADING_GOURAUD_AD || shading == C2G_SHADING_GOURAUD_ADS
                      ? C2R_RGB : 0)
                 | (lit ? C2R_EYE | C2R_NORMAL : 0) | (sampled ? C2R_UV : 0);
    per_corner = 4 + (attributes & C2R_RGB ? 3 : 0) + (lit ? 6 : 0) + (sampled ? 2 : 0);

    /* The buffers: the background, and depth 1 (0 for two mistakes). */
    pixels = (size_t)W * H;
    framebuffer = (unsigned char *)malloc(3 * pixels);
    depthbuffer = (float *)malloc(pixels * sizeof *depthbuffer);
    texture_name = (char *)malloc(strlen(argv[2]) + 16);
    if (!framebuffer || !depthbuffer || !texture_name) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    sprintf(texture_name, "%s.texture.ppm", argv[2]);   /* the texture as it was read */
    for (i = 0; i < 3; i++) background[i] = s.background[i], clear[i] = byte(s.background[i]);
    for (i = 0; i < (int)pixels; i++) {
        memcpy(framebuffer + 3 * i, clear, 3);
        depthbuffer[i] = 1;
#if defined(MISTAKE_DEPTH_CLEARED_TO_ZERO) || defined(MISTAKE_FARTHEST_WINS)
        depthbuffer[i] = 0;                        /* MISTAKE: cleared to 0 */
#endif
    }

    if (!(out = c2r_open(argv[2]))) return 1;
    c2r_write_model(out, base_name(s.model));
    c2r_write_window(out, W, H);
    c2r_write_origin(out, C2R_ORIGIN_BOTTOM_LEFT);
    c2r_write_subpixel(out, SUBPIXEL_BITS);
    c2r_write_shading(out, shading);
    c2r_write_color(out, s.color);
    c2r_write_background(out, background);
    if (lit) {
        real ia[3], il[3], att[3];
        for (i = 0; i < 3; i++) ia[i] = IA[i], il[i] = IL[i], att[i] = ATTENUATION[i];
        c2r_write_light(out, s.light);
        c2r_write_matrix(out, M);
        c2r_write_lighting(out, ia, il, KA, KD, KS, SHININESS, att);
    }
    if (sampled) c2r_write_texture(out, base_name(texture_name), filter);
    c2r_write_buffer_names(out, argv[2]);             /* TRACE.ppm, TRACE.pfm */
    c2r_write_attributes(out, attributes);

    for (t = 0; t < m.count; t++) {
        const triangle *tri = &m.tri[t];
        clip_vertex poly[9];
        corner c[9];
        real area = 0;
        int k, j;
        /* Each corner: eye position and normal (M's rotation: M is rigid), clip coordinates,
         * Gouraud's colour lit here, s and t. */
        for (i = 0; i < 3; i++) {
            vec4 eye = mat_vec(M, v4(tri->p[i], 1)), normal = mat_vec(M, v4(tri->n[i], 0));
            vec3 e = v3(eye.x, eye.y, eye.z), n = v3(normal.x, normal.y, normal.z), rgb = color;
            poly[i].p = mat_vec(P, eye);
            if (shading == C2G_SHADING_GOURAUD_AD || shading == C2G_SHADING_GOURAUD_ADS)
                rgb = mul(color, illumination(e, n, shading == C2G_SHADING_GOURAUD_ADS, 0));
            to_array(rgb, poly[i].a + RGB);
            to_array(e, poly[i].a + EYE);
            to_array(n, poly[i].a + NORMAL);
            poly[i].a[UV] = tri->uv[i][0], poly[i].a[UV + 1] = tri->uv[i][1];
        }
        k = clip_polygon(poly, 3);
        if (k < 3) continue;
        /* Divided and mapped: window x, y (y up), depth z·0.5 + 0.5, q = 1/w. */
        for (i = 0; i < k; i++) {
            real q = 1 / poly[i].p.w;
            c[i].win[0] = (poly[i].p.x * q + 1) * (real)W / 2;
            c[i].win[1] = (poly[i].p.y * q + 1) * (real)H / 2;
            c[i].win[2] = poly[i].p.z * q * (real)0.5 + (real)0.5;
            c[i].win[3] = q;
            memcpy(c[i].a, poly[i].a, sizeof c[i].a);
        }
        for (i = 0; i < k; i++)
            area += c[i].win[0] * c[(i + 1) % k].win[1] - c[(i + 1) % k].win[0] * c[i].win[1];
        if ((s.culling == C2G_CULL_CCW && area <= 0) || (s.culling == C2G_CULL_CW && area >= 0))
            continue;
        /* A fan from the first corner; each triangle written, then drawn. */
        for (j = 1; j + 1 < k; j++) {
            corner fan[3];
            real numbers[3 * 17];
            fan[0] = c[0], fan[1] = c[j], fan[2] = c[j + 1];
            for (i = 0; i < 3; i++) {
                real *n = numbers + i * per_corner;
                memcpy(n, fan[i].win, 4 * sizeof(real));
                n += 4;
                if (attributes & C2R_RGB) memcpy(n, fan[i].a + RGB, 3 * sizeof(real)), n += 3;
                if (lit) memcpy(n, fan[i].a + EYE, 6 * sizeof(real)), n += 6;
                if (sampled) memcpy(n, fan[i].a + UV, 2 * sizeof(real));
            }
            c2r_write_tri(out, t, numbers);
            draw_triangle(fan);
        }
    }
    if (!c2r_close(out)) return 1;

#ifdef MISTAKE_ROWS_BOTTOM_FIRST
    order = C2R_BOTTOM_ROW_FIRST;                  /* MISTAKE: both buffers upside down */
#endif
#ifdef MISTAKE_CHANNELS_SWAPPED
    for (i = 0; i < (int)pixels; i++) {            /* MISTAKE: blue, green, red */
        unsigned char r = framebuffer[3 * i];
        framebuffer[3 * i] = framebuffer[3 * i + 2], framebuffer[3 * i + 2] = r;
    }
#endif
    if (!c2r_write_buffers(argv[2], framebuffer, depthbuffer, W, H, order)
        || (sampled && !c2r_write_ppm(texture_name, levels[0].rgb, levels[0].w, levels[0].h,
                                      C2R_TOP_ROW_FIRST)))
        return 1;
    for (i = 0; i < level_count; i++) free(levels[i].rgb);
    free(texture_name);
    free(framebuffer);
    free(depthbuffer);
    free(m.tri);
    c2g_free_scene(&s);
    return 0;
}
