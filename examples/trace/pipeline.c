/* pipeline.c: the Close2GL assignment's geometry pipeline in one small C99 program, writing a
 * close2gl trace of the frame a scene file asks for.
 *
 *     pipeline SCENE TRACE [yup|ydown|unit]
 *
 * The third argument is the 2D system the output is given in (what the program would have passed
 * gluOrtho2D): yup is ortho2d 0 W 0 H (the default), ydown 0 W H 0, unit 0 1 0 1.
 *
 * Compile-time switches (see README.md):
 *   -DMISTAKE_<ID>    make one of the catalogued mistakes (several at once combine)
 *   -DCLOSE2GL_FLOAT  compute in float, as a float32 program does
 *   -DROTATE_CLOCKWISE rotate the camera the other way (a reversed but consistent convention)
 *   -DFAN             write a clipped polygon as a fan of triangles instead of one poly line
 */
#define CLOSE2GL_TRACE_IMPLEMENTATION
#include "close2gl_trace.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef c2g_real real;
#define PI 3.14159265358979323846

/* ---- vectors and matrices ------------------------------------------------------------------ */

typedef struct { real x, y, z; } vec3;
typedef struct { real x, y, z, w; } vec4;

static vec3 v3(real x, real y, real z) { vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static vec3 add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec3 sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec3 scale(vec3 a, real s) { return v3(a.x * s, a.y * s, a.z * s); }
static real dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static vec3 normalize(vec3 a) { return scale(a, (real)(1 / sqrt(dot(a, a)))); }
static vec3 from_array(const real a[3]) { return v3(a[0], a[1], a[2]); }
static void to_array(vec3 a, real out[3]) { out[0] = a.x; out[1] = a.y; out[2] = a.z; }

/* 4x4 matrices are real[16], row by row: m[4*row + column]. */
static void mat_mul(const real a[16], const real b[16], real out[16])
{
    int r, c, k;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++) {
            real sum = 0;
            for (k = 0; k < 4; k++) sum += a[4 * r + k] * b[4 * k + c];
            out[4 * r + c] = sum;
        }
}

static vec4 mat_vec(const real m[16], vec4 p)
{
    vec4 r;
    r.x = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * p.w;
    r.y = m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7] * p.w;
    r.z = m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11] * p.w;
    r.w = m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15] * p.w;
    return r;
}

/* ---- the model ----------------------------------------------------------------------------- */

typedef struct {
    vec3 p[3];      /* corners, in the file's order */
    vec3 normal;    /* the file's face normal (.obj: the mean of the corner normals) */
} triangle;

typedef struct {
    triangle *tri;
    int count, capacity;
} mesh;

static int push_triangle(mesh *m, triangle t)
{
    if (m->count == m->capacity) {  /* grow by doubling: never trust a header's count */
        int capacity = m->capacity ? 2 * m->capacity : 64;
        triangle *grown = (triangle *)realloc(m->tri, (size_t)capacity * sizeof *grown);
        if (!grown) return 0;
        m->tri = grown;
        m->capacity = capacity;
    }
    m->tri[m->count++] = t;
    return 1;
}

/* A model file read line by line, each line cut into fields. */
typedef struct {
    FILE *f;
    const char *path;
    int line;
    char text[4096];   /* the line as read (for messages) */
    char copy[4096];
    char *field[24];
    int count;         /* fields on this line (25 = too many) */
    int at_end;        /* next_line found no more lines */
} reader;

/* Reads the next line that is not blank; 0 at the end of the file. */
static int next_line(reader *r)
{
    size_t len;
    do {
        if (!fgets(r->text, sizeof r->text, r->f)) {
            r->at_end = 1;
            return 0;
        }
        r->line++;
        len = strcspn(r->text, "\r\n");
        r->text[len] = '\0';
        strcpy(r->copy, r->text);
        r->count = c2g_split(r->copy, r->field, 24);
    } while (r->count == 0);
    return 1;
}

/* "file:line: expected WHAT, found 'the line'"; returns 0. */
static int bad(const reader *r, const char *what)
{
    if (r->at_end)
        fprintf(stderr, "%s:%d: expected %s, found the end of the file\n", r->path, r->line, what);
    else
        fprintf(stderr, "%s:%d: expected %s, found '%s'\n", r->path, r->line, what,
                r->text + strspn(r->text, " \t"));
    return 0;
}

/* Does the current line start with the words of `words` (space separated) and then hold exactly
 * `numbers` numbers? They are stored in out. */
static int line_is(reader *r, const char *words, int numbers, real *out)
{
    char buffer[64], *word[8];
    int i, count;
    strcpy(buffer, words);
    count = c2g_split(buffer, word, 8);
    if (r->count != count + numbers) return 0;
    for (i = 0; i < count; i++)
        if (strcmp(r->field[i], word[i]) != 0) return 0;
    for (i = 0; i < numbers; i++)
        if (!c2g_parse_real(r->field[count + i], &out[i])) return 0;
    return 1;
}

/* The course's .in format (tri-format.md), with the variants real files have. */
static int load_in(reader *r, mesh *m)
{
    static const char *const material[4] = {"ambient color", "diffuse color", "specular color",
                                            "material shine"};
    char what[64];
    real x[9], claimed, materials;
    int i, k, textured = 0, more;
    triangle t;

    if (!next_line(r) || r->count < 3 || strcmp(r->field[0], "Object")
        || strcmp(r->field[1], "name"))
        return bad(r, "'Object name = NAME'");
    if (!next_line(r) || !line_is(r, "# triangles =", 1, &claimed))
        return bad(r, "'# triangles = N'");
    if (!next_line(r) || !line_is(r, "Material count =", 1, &materials) || materials < 0
        || materials > 10000 || materials != (int)materials)
        return bad(r, "'Material count = M'");
    for (i = 0; i < 4 * (int)materials; i++)
        if (!next_line(r) || !line_is(r, material[i % 4], i % 4 == 3 ? 1 : 3, x)) {
            sprintf(what, "'%s %s'", material[i % 4], i % 4 == 3 ? "s" : "r g b");
            return bad(r, what);
        }
    /* Then an optional "Texture = YES|NO" line and one comment line of any wording. */
    more = next_line(r);
    if (more && r->count == 3 && !strcmp(r->field[0], "Texture") && !strcmp(r->field[1], "=")) {
        if (strcmp(r->field[2], "YES") && strcmp(r->field[2], "NO"))
            return bad(r, "'Texture = YES|NO'");
        textured = !strcmp(r->field[2], "YES");
        more = next_line(r);
    }
    if (more && strcmp(r->field[0], "v0") != 0) more = next_line(r);  /* the comment line */

    /* The triangles: v0, v1, v2 and the face normal, until the end of the file. */
    for (; more; more = next_line(r)) {
        for (k = 0; k < 3; k++) {
            char tag[3] = {'v', (char)('0' + k), '\0'};
            if ((k > 0 && !next_line(r)) || !line_is(r, tag, textured ? 9 : 7, x)) {
                sprintf(what, "'v%d x y z nx ny nz material%s'", k, textured ? " s t" : "");
                return bad(r, what);
            }
            t.p[k] = v3(x[0], x[1], x[2]);
        }
        if (!next_line(r) || !line_is(r, "face normal", 3, x))
            return bad(r, "'face normal nx ny nz'");
        t.normal = v3(x[0], x[1], x[2]);
        if (!push_triangle(m, t)) return bad(r, "memory for another triangle");
    }
    if (claimed != m->count)
        fprintf(stderr, "%s: warning: the header says %.0f triangles, the file has %d\n",
                r->path, (double)claimed, m->count);
    return 1;
}

/* One OBJ index ("-1" is the last one so far); 0 when absent. */
static int obj_index(const char *s, char **end, int count)
{
    long i = strtol(s, end, 10);
    if (*end == s) return 0;
    if (i < 0) i += count + 1;
    return i >= 1 && i <= count ? (int)i : -1;
}

/* Wavefront OBJ: v, vn and f (v, v/vt, v//vn, v/vt/vn; negative indices); other lines ignored.
 * A polygon becomes a fan of triangles from its first corner. */
static int load_obj(reader *r, mesh *m)
{
    vec3 *v = NULL, *vn = NULL;
    int nv = 0, nvn = 0, capv = 0, capvn = 0, ok = 0, i, k;
    real x[4];
    while (next_line(r)) {
        if (!strcmp(r->field[0], "v") || !strcmp(r->field[0], "vn")) {
            int is_normal = r->field[0][1] == 'n';
            vec3 **array = is_normal ? &vn : &v;
            int *count = is_normal ? &nvn : &nv, *cap = is_normal ? &capvn : &capv;
            if (is_normal ? !line_is(r, "vn", 3, x)
                          : !line_is(r, "v", 3, x) && !line_is(r, "v", 4, x)) { /* w is ignored */
                bad(r, is_normal ? "'vn x y z'" : "'v x y z'");
                goto done;
            }
            if (*count == *cap) {
                vec3 *grown;
                *cap = *cap ? 2 * *cap : 256;
                grown = (vec3 *)realloc(*array, (size_t)*cap * sizeof *grown);
                if (!grown) { bad(r, "memory for another vertex"); goto done; }
                *array = grown;
            }
            (*array)[(*count)++] = v3(x[0], x[1], x[2]);
        } else if (!strcmp(r->field[0], "f")) {
            int corner[23], normal[23], corners = r->count - 1;
            if (corners < 3 || corners > 23) { bad(r, "'f' with 3 to 23 corners"); goto done; }
            for (i = 0; i < corners; i++) {
                char *s = r->field[1 + i], *end;
                corner[i] = obj_index(s, &end, nv);
                normal[i] = 0;
                if (corner[i] > 0 && *end == '/') {        /* v/vt, v//vn or v/vt/vn */
                    s = end + 1;
                    if (*s != '/') {                       /* vt: not used here */
                        (void)strtol(s, &end, 10);
                        if (end == s) corner[i] = -1;
                        s = end;
                    }
                    if (*s == '/' && (normal[i] = obj_index(s + 1, &end, nvn)) <= 0) corner[i] = -1;
                }
                if (corner[i] <= 0 || *end != '\0') {
                    bad(r, "'f' corners v, v/vt, v//vn or v/vt/vn, of vertices read so far");
                    goto done;
                }
            }
            for (k = 1; k + 1 < corners; k++) {
                int c[3];
                triangle t;
                c[0] = 0, c[1] = k, c[2] = k + 1;
                t.normal = v3(0, 0, 0);  /* the mean of the corner normals (a missing one adds 0) */
                for (i = 0; i < 3; i++) {
                    t.p[i] = v[corner[c[i]] - 1];
                    if (normal[c[i]])
                        t.normal = add(t.normal, scale(vn[normal[c[i]] - 1], (real)(1.0 / 3)));
                }
                if (!push_triangle(m, t)) { bad(r, "memory for another triangle"); goto done; }
            }
        }
    }
    ok = 1;
done:
    free(v);
    free(vn);
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
    r.f = fopen(path, "rb");
    if (!r.f) {
        perror(path);
        return 0;
    }
    if (len > 4 && (!strcmp(path + len - 4, ".obj") || !strcmp(path + len - 4, ".OBJ")))
        ok = load_obj(&r, m);
    else
        ok = load_in(&r, m);
    fclose(r.f);
    if (ok && m->count == 0) {
        fprintf(stderr, "%s: expected at least one triangle, found none\n", path);
        ok = 0;
    }
    if (!ok) free(m->tri);     /* never a half-read model */
    return ok;
}

/* ---- the camera ---------------------------------------------------------------------------- */

typedef struct {
    vec3 c, u, v, n;           /* centre of projection and axes; the camera looks along -n */
    real hfov, vfov, znear, zfar;
} camera;

/* The u a program sets from v and n: v x n; a left-handed one sets n x v. */
static vec3 u_from(vec3 v, vec3 n)
{
#ifdef MISTAKE_LEFT_HANDED
    return cross(n, v);  /* MISTAKE: u = n x v */
#else
    return cross(v, n);
#endif
}

/* The v it sets from n and u: n x u, or u x n in its left-handed frame (still v = (n x v) x n). */
static vec3 v_from(vec3 n, vec3 u)
{
#ifdef MISTAKE_LEFT_HANDED
    return cross(u, n);
#else
    return cross(n, u);
#endif
}

/* The bounding box's centre and the radius of the sphere around the box. */
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

/* "Rendering the object in the centre of the windows": looking along -z at the bounding box's
 * centre, at the distance where the bounding sphere fits both fields of view. */
static camera frame(const mesh *m, const c2g_scene *s)
{
    vec3 centre;
    real r, d;
    camera cam;
    bounding_sphere(m, &centre, &r);
    if (!(r > 0)) r = 1;       /* a model that is a single point: any size will do */
    cam.hfov = s->hfov;
    cam.vfov = s->vfov;
    d = (real)(r / sin((s->hfov < s->vfov ? s->hfov : s->vfov) * PI / 360));
    cam.c = add(centre, v3(0, 0, d));
    cam.v = v3(0, 1, 0);
    cam.n = v3(0, 0, 1);
    cam.u = u_from(cam.v, cam.n);
    /* near hugs the model but stays in front of it (0 < near < d - r); far leaves room behind. */
    cam.znear = s->has_near ? s->znear : (real)(0.5 * (d - r));
    if (!(cam.znear > 0)) cam.znear = (real)(0.01 * r);
    cam.zfar = s->has_far ? s->zfar : d + 2 * r;
    if (cam.zfar <= cam.znear) {   /* only one of them was given, and it crossed the other */
        if (s->has_near) cam.zfar = cam.znear + 2 * r;
        else cam.znear = (real)(0.01 * cam.zfar);
    }
    return cam;
}

static vec3 *axis(camera *cam, char name)
{
    return name == 'u' ? &cam->u : name == 'v' ? &cam->v : &cam->n;
}

/* The scene's moves, with the camera's own axes. */
static void apply_motion(camera *cam, const c2g_motion *m, vec3 lookat)
{
    vec3 u = cam->u, v = cam->v, n = cam->n;
    real angle = (real)(m->amount * PI / 180), cs, sn;
#ifdef ROTATE_CLOCKWISE
    angle = -angle;       /* a program that turns the other way (consistently) */
#endif
    cs = (real)cos(angle);
    sn = (real)sin(angle);
    if (m->kind == 'm') {
        cam->c = add(cam->c, scale(*axis(cam, m->axis), m->amount));
    } else if (m->kind == 'r') {         /* right-hand rule about the named axis */
        if (m->axis == 'u') {
            cam->v = add(scale(v, cs), scale(n, sn));
            cam->n = sub(scale(n, cs), scale(v, sn));
        } else if (m->axis == 'v') {
            cam->n = add(scale(n, cs), scale(u, sn));
            cam->u = sub(scale(u, cs), scale(n, sn));
        } else {
            cam->u = add(scale(u, cs), scale(v, sn));
            cam->v = sub(scale(v, cs), scale(u, sn));
        }
    } else {                             /* orbit: move, then look back at the look-at point */
        cam->c = add(cam->c, scale(*axis(cam, m->axis), m->amount));
        cam->n = normalize(sub(cam->c, lookat));
        if (m->axis == 'u') {
            cam->u = normalize(u_from(cam->v, cam->n));
            cam->v = v_from(cam->n, cam->u);
        } else {
            cam->v = normalize(v_from(cam->n, cam->u));
            cam->u = u_from(cam->v, cam->n);
        }
    }
}

/* ---- the three matrices -------------------------------------------------------------------- */

/* M: world to camera coordinates. Rows u, v, n; translations -c.u, -c.v, -c.n. */
static void modelview(const camera *cam, real M[16])
{
    vec3 t = v3(-dot(cam->c, cam->u), -dot(cam->c, cam->v), -dot(cam->c, cam->n));
#ifdef MISTAKE_TRANSLATION_UNROTATED
    t = scale(cam->c, -1);     /* MISTAKE: -c, not rotated into the camera's axes */
#endif
#ifdef MISTAKE_TRANSLATION_SIGN
    t = scale(t, -1);          /* MISTAKE: +c.u, +c.v, +c.n */
#endif
    M[0] = cam->u.x, M[1] = cam->u.y, M[2] = cam->u.z, M[3] = t.x;
    M[4] = cam->v.x, M[5] = cam->v.y, M[6] = cam->v.z, M[7] = t.y;
    M[8] = cam->n.x, M[9] = cam->n.y, M[10] = cam->n.z, M[11] = t.z;
    M[12] = 0, M[13] = 0, M[14] = 0, M[15] = 1;
#ifdef MISTAKE_MODELVIEW_TRANSPOSED
    {                          /* MISTAKE: M used transposed */
        int r, c;
        for (r = 0; r < 4; r++)
            for (c = r + 1; c < 4; c++) {
                real swap = M[4 * r + c];
                M[4 * r + c] = M[4 * c + r];
                M[4 * c + r] = swap;
            }
    }
#endif
}

/* P: glFrustum(left, right, bottom, top, near, far) with right = near tan(hfov/2),
 * top = near tan(vfov/2), left = -right, bottom = -top. */
static void projection(const camera *cam, real P[16])
{
    real h = cam->hfov, v = cam->vfov, half = (real)0.5, radians = (real)(PI / 180);
    real n = cam->znear, f = cam->zfar, r, t;
    int i;
#ifdef MISTAKE_FOVS_SWAPPED
    h = cam->vfov, v = cam->hfov;  /* MISTAKE: hfov taken for the vertical extent, and vice versa */
#endif
#ifdef MISTAKE_FOV_NOT_HALVED
    half = 1;                      /* MISTAKE: the whole angle, not half of it */
#endif
#ifdef MISTAKE_FOV_IN_DEGREES
    radians = 1;                   /* MISTAKE: degrees handed to tan as if they were radians */
#endif
    t = (real)(n * tan(v * half * radians));
    r = (real)(n * tan(h * half * radians));
#ifdef MISTAKE_ASPECT_FROM_ANGLES
    r = t * h / v;                 /* MISTAKE: the aspect ratio taken as hfov / vfov */
#endif
    /* glFrustum's 2n/(r - l) is n/r, and its (r + l)/(r - l) is 0, when l = -r (so for t, b). */
    for (i = 0; i < 16; i++) P[i] = 0;
    P[0] = n / r;
    P[5] = n / t;
    P[10] = -(f + n) / (f - n), P[11] = -2 * f * n / (f - n);
    P[14] = -1;
#ifdef MISTAKE_DEPTH_ROW_SIGN
    P[8] = -P[8], P[9] = -P[9], P[10] = -P[10], P[11] = -P[11];  /* MISTAKE: third row negated */
#endif
}

/* V: NDC x, y in [-1, 1] onto ortho2d L R B T; z onto [0, 1] (not compared). */
static void viewport(const real o[4], real V[16])
{
    real L = o[0], R = o[1], B = o[2], T = o[3];
    real sx = (R - L) / 2, sy = (T - B) / 2;
    int i;
#ifdef MISTAKE_VIEWPORT_FULL_SCALE
    sx = R - L, sy = T - B;        /* MISTAKE: scaled by the whole width and height */
#endif
#ifdef MISTAKE_VIEWPORT_Y_FLIPPED
    sy = -sy;                      /* MISTAKE: y turned upside down */
#endif
    for (i = 0; i < 16; i++) V[i] = 0;
    V[0] = sx, V[3] = (R + L) / 2;
    V[5] = sy, V[7] = (T + B) / 2;
    V[10] = (real)0.5, V[11] = (real)0.5;
    V[15] = 1;
}

/* ---- clipping ------------------------------------------------------------------------------ */

/* The clipping the program does: the scene's C2G_CLIP_... or, with a mistake, this. */
enum { DIVIDE_FIRST = 3 };

static int outside_volume(vec4 p)
{
    return !(fabs(p.x) <= p.w && fabs(p.y) <= p.w && fabs(p.z) <= p.w && p.w > 0);
}

/* Signed distance to plane i of x >= -w, x <= w, y >= -w, y <= w, z >= -w, z <= w: inside >= 0. */
static real plane_distance(vec4 p, int i)
{
    real s = i % 2 ? -1 : 1;
    real coordinate = i < 2 ? p.x : i < 4 ? p.y : p.z;
    return p.w + s * coordinate;
}

/* A corner at or behind the eye (w <= 0) is outside the near plane even where z >= -w (which only
 * a wrong P allows). */
static int inside(vec4 p, int i) { return plane_distance(p, i) >= 0 && (i != 4 || p.w > 0); }

/* Where the edge from `in` (inside) to `out` (outside) crosses plane i. Always interpolated from
 * the inside corner, so the two triangles sharing an edge get the very same point. */
static vec4 crossing(vec4 in, vec4 out, int i)
{
    real din = plane_distance(in, i), dout = plane_distance(out, i), t = din / (din - dout);
    vec4 p;
    p.x = in.x + t * (out.x - in.x);
    p.y = in.y + t * (out.y - in.y);
    p.z = in.z + t * (out.z - in.z);
    p.w = in.w + t * (out.w - in.w);
    return p;
}

/* Sutherland-Hodgman against the six planes, in order, skipping those no corner is outside of.
 * poly has room for 9 corners (3, plus at most one per plane). Returns the corner count (< 3:
 * nothing left) and sets *cut when some plane cut. */
static int clip_polygon(vec4 poly[9], int k, int *cut)
{
    vec4 in[9];
    int i, j, kin, any;
    *cut = 0;
    for (i = 0; i < 6 && k >= 3; i++) {
        for (any = 0, j = 0; j < k; j++) any |= !inside(poly[j], i);
        if (!any) continue;
        *cut = 1;
        /* After the x and y planes every corner has w >= 0, so a corner outside the near plane
         * only for its w is exactly at w = 0 (the eye): there is no crossing to compute. */
        if (i == 4)
            for (j = 0; j < k; j++)
                if (poly[j].w <= 0 && plane_distance(poly[j], 4) >= 0) return 0;
        memcpy(in, poly, (size_t)k * sizeof *in);
        kin = k;
        k = 0;
        for (j = 0; j < kin; j++) {
            vec4 a = in[j], b = in[(j + 1) % kin];         /* the edge a -> b */
            int ia = inside(a, i), ib = inside(b, i);
            if (ia) poly[k++] = a;
            /* Where the edge crosses the plane, a new corner (a corner exactly on the plane is
             * inside and is its own crossing: it is not emitted twice). */
            if (ia && !ib && plane_distance(a, i) > 0) poly[k++] = crossing(a, b, i);
            if (!ia && ib && plane_distance(b, i) > 0) poly[k++] = crossing(b, a, i);
        }
    }
    return k;
}

/* ---- culling ------------------------------------------------------------------------------- */

/* What decides a back face: the winding on screen, or (two mistakes) a world-space test. */
enum { BY_WINDING, BY_FILE_NORMALS, BY_VIEW_AXIS };
#if defined(MISTAKE_CULLING_BY_FILE_NORMALS)
#define CULLING_TEST BY_FILE_NORMALS
#elif defined(MISTAKE_CULLING_BY_VIEW_AXIS)
#define CULLING_TEST BY_VIEW_AXIS
#else
#define CULLING_TEST BY_WINDING
#endif

/* Is this piece of mesh triangle t, drawn with the k 2D corners xyz (x y z each), culled? */
static int culled(const c2g_scene *s, const camera *cam, const triangle *t, const real o[4],
                  const real *xyz, int k)
{
    int front_ccw = s->culling == C2G_CULL_CCW, i;
    real area = 0, facing;
    if (s->culling == C2G_CULL_OFF) return 0;
#ifdef MISTAKE_NEVER_CULLS
    return 0;                          /* MISTAKE: culling declared, nothing culled */
#endif
#ifdef MISTAKE_CULLING_INVERTED
    front_ccw = !front_ccw;            /* MISTAKE: the opposite winding taken as front */
#endif
#ifdef MISTAKE_CULLING_IGNORES_FRONT_FACE
    front_ccw = 1;                     /* MISTAKE: counter-clockwise front, whatever is declared */
#endif
    if (CULLING_TEST == BY_FILE_NORMALS) {
        /* MISTAKE: the file's normal against the direction to the eye */
        facing = dot(t->normal, sub(cam->c, t->p[0]));
        return front_ccw ? facing < 0 : facing > 0;
    }
    if (CULLING_TEST == BY_VIEW_AXIS) {
        /* MISTAKE: the world-space normal against the camera's n */
        facing = dot(cross(sub(t->p[1], t->p[0]), sub(t->p[2], t->p[0])), cam->n);
        return front_ccw ? facing < 0 : facing > 0;
    }
    /* Twice the signed area in the ortho2d system, counter-clockwise positive when its axes point
     * right and up; times the sign of (R - L)(T - B) it is the winding as seen on screen. */
    for (i = 0; i < k; i++) {
        const real *p = xyz + 3 * i, *q = xyz + 3 * ((i + 1) % k);
        area += p[0] * q[1] - q[0] * p[1];
    }
    if ((o[1] - o[0]) * (o[3] - o[2]) < 0) area = -area;
    return front_ccw ? area <= 0 : area >= 0;   /* a triangle seen edge-on is culled either way */
}

/* ---- the frame ----------------------------------------------------------------------------- */

int main(int argc, char **argv)
{
    c2g_scene s;
    mesh m;
    camera cam;
    vec3 lookat;
    real M[16], P[16], V[16], PM[16], o[4], radius;
    const char *name;
    FILE *out;
    int i, t, clipping;

    if (argc < 3 || argc > 4
        || (argc == 4 && strcmp(argv[3], "yup") && strcmp(argv[3], "ydown")
            && strcmp(argv[3], "unit"))) {
        fprintf(stderr, "usage: %s SCENE TRACE [yup|ydown|unit]\n", argv[0]);
        return 2;
    }
    if (!c2g_read_scene(argv[1], &s) || !load_model(s.model, &m)) return 1;

    /* The camera: the scene's, or framed; then the scene's moves, in order. */
    if (s.framed) {
        cam = frame(&m, &s);
    } else {
        cam.c = from_array(s.position);
        cam.v = from_array(s.v);
        cam.n = from_array(s.n);
#ifdef MISTAKE_LEFT_HANDED
        cam.u = u_from(cam.v, cam.n);
#else
        cam.u = from_array(s.u);
#endif
        cam.hfov = s.hfov, cam.vfov = s.vfov, cam.znear = s.znear, cam.zfar = s.zfar;
    }
    if (s.has_lookat) lookat = from_array(s.lookat);
    else bounding_sphere(&m, &lookat, &radius);
    for (i = 0; i < s.motion_count; i++) apply_motion(&cam, &s.motions[i], lookat);

    /* The 2D system the output is given in, as gluOrtho2D(L, R, B, T) would have it. */
    o[0] = 0, o[1] = (real)s.width, o[2] = 0, o[3] = (real)s.height;
    if (argc == 4 && !strcmp(argv[3], "ydown")) o[2] = (real)s.height, o[3] = 0;
    if (argc == 4 && !strcmp(argv[3], "unit")) o[1] = 1, o[3] = 1;

    modelview(&cam, M);
    projection(&cam, P);
    viewport(o, V);
#ifdef MISTAKE_PRODUCT_ORDER
    mat_mul(M, P, PM);   /* MISTAKE: M.P instead of P.M */
#else
    mat_mul(P, M, PM);
#endif
    clipping = s.clipping;
#ifdef MISTAKE_NO_CLIPPING
    clipping = C2G_CLIP_NONE;       /* MISTAKE: no clipping, whatever the scene says */
#endif
#ifdef MISTAKE_DIVIDE_BEFORE_CLIP
    clipping = DIVIDE_FIRST;        /* MISTAKE: divide, then test x, y; whatever the scene says */
#endif

    out = fopen(argv[2], "w");
    if (!out) {
        perror(argv[2]);
        return 1;
    }
    name = strrchr(s.model, '/') ? strrchr(s.model, '/') + 1 : s.model;
    c2g_write_header(out);
    c2g_write_model(out, name);
    c2g_write_triangles(out, m.count);
    c2g_write_window(out, s.width, s.height);
    c2g_write_ortho2d(out, o[0], o[1], o[2], o[3]);
    {
        real c[3], u[3], v[3], n[3];
        to_array(cam.c, c), to_array(cam.u, u), to_array(cam.v, v), to_array(cam.n, n);
        c2g_write_camera(out, c, u, v, n, cam.hfov, cam.vfov, cam.znear, cam.zfar);
    }
    c2g_write_culling(out, s.culling);
    c2g_write_clipping(out, s.clipping);
    c2g_write_mode(out, s.mode);
    c2g_write_matrix(out, 'M', M);
    c2g_write_matrix(out, 'P', P);
    c2g_write_matrix(out, 'V', V);

    for (t = 0; t < m.count; t++) {
        vec4 poly[9];
        real clip[12], xyz[27];
        int corners = 3, cut = 0, drop = 0, w_zero = 0;

        /* 1-2. World to clip coordinates. */
        for (i = 0; i < 3; i++) {
            vec4 p;
            p.x = m.tri[t].p[i].x, p.y = m.tri[t].p[i].y, p.z = m.tri[t].p[i].z, p.w = 1;
            poly[i] = mat_vec(PM, p);
            clip[4 * i] = poly[i].x, clip[4 * i + 1] = poly[i].y;
            clip[4 * i + 2] = poly[i].z, clip[4 * i + 3] = poly[i].w;
            w_zero |= poly[i].w == 0;
        }
        c2g_write_clip(out, t, clip);

        /* 3. Clipping. No corner at w = 0 may reach the division. */
        if (clipping == C2G_CLIP_SIMPLE) {          /* the whole triangle, or nothing */
            for (i = 0; i < 3; i++) drop |= outside_volume(poly[i]);
        } else if (clipping == C2G_CLIP_FULL) {
            corners = clip_polygon(poly, 3, &cut);
            drop = corners < 3;
        } else if (clipping == C2G_CLIP_NONE) {
            drop = w_zero;
        } else {                                    /* (a mistake) x and y tested after dividing */
            drop = w_zero;
            for (i = 0; i < 3 && !drop; i++)
                drop = fabs(poly[i].x / poly[i].w) > 1 || fabs(poly[i].y / poly[i].w) > 1;
        }
        if (drop) continue;

        /* 4-5. Perspective division, then the viewport (its z row is not used: z stays NDC). */
        for (i = 0; i < corners; i++) {
            vec4 ndc, p;
            ndc.x = poly[i].x / poly[i].w, ndc.y = poly[i].y / poly[i].w;
            ndc.z = poly[i].z / poly[i].w, ndc.w = 1;
            p = mat_vec(V, ndc);
            xyz[3 * i] = p.x, xyz[3 * i + 1] = p.y, xyz[3 * i + 2] = ndc.z;
        }

        /* 6. Culling, then "drawing": the trace's tri or poly lines. */
        if (culled(&s, &cam, &m.tri[t], o, xyz, corners)) continue;
        if (!cut) {
            c2g_write_tri(out, t, xyz, 3);
        } else {
#ifdef FAN
            int k;
            for (k = 1; k + 1 < corners; k++) {
                real fan[9];
                memcpy(fan, xyz, 3 * sizeof *fan);
                memcpy(fan + 3, xyz + 3 * k, 6 * sizeof *fan);
                c2g_write_tri(out, t, fan, 3);
            }
#else
            c2g_write_poly(out, t, corners, xyz, 3);
#endif
        }
    }
    c2g_write_end(out);
    if (fclose(out) != 0) {
        perror(argv[2]);
        return 1;
    }
    free(m.tri);
    c2g_free_scene(&s);
    return 0;
}
