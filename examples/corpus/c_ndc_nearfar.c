/* c_ndc_nearfar.c: a C program whose GPU does the rest. It keeps OpenGL's habits: matrices in
 * column-major double[16] (m[4*column + row], as glLoadMatrixd takes them), clipping against the
 * near and far planes only (a triangle with a corner outside them is dropped, the rest is sent
 * whole: the GPU's 2D rasteriser cuts at the window's edge), culling by the winding of NDC x, y,
 * and NDC handed to the GPU, which does the viewport.
 *
 *     c_ndc_nearfar SCENE TRACE
 *
 * Variant: -DDECLARE_SIMPLE writes `clipping simple` (the assignment's rule, which it does not
 * follow: it keeps triangles reaching outside x and y) instead of `clipping simple near_far`.
 *
 * Lines ending in "[trace]" were added only to write the trace.
 *
 * expect cube_front: agree
 * expect knot_turned: agree
 * expect knot_through: agree
 * expect knot_cw: agree
 * expect inside_cube: agree
 * expect knot_aside: agree
 * expect knot_through -DDECLARE_SIMPLE: differs stage=clipping unexplained
 * expect knot_aside -DDECLARE_SIMPLE: differs stage=clipping names=no_clipping fits=clipping_simple_near_far
 * expect-grade cube: 200
 * expect-grade cube -DIDENTITY_V: 200
 * expect-grade cube -DDECLARE_SIMPLE: simple_clipping=3 synchronized=22
 */
#define CLOSE2GL_TRACE_IMPLEMENTATION /* [trace] */
#include "close2gl_trace.h"
#include "model.h"

#include <math.h>

typedef struct { double x, y, z, w; } vec4;
typedef struct { double x, y, z; } vec3;

static vec3 vec(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
static vec3 along(vec3 a, double s, vec3 b) { return vec(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z); }
static double dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 cross(vec3 a, vec3 b) { return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static vec3 unit(vec3 a) { return along(vec(0, 0, 0), 1 / sqrt(dot(a, a)), a); }

typedef struct { vec3 eye, u, v, n; double fovx, fovy, znear, zfar; } Camera;

/* m = a * b, column-major */
static void mul(const double *a, const double *b, double *m)
{
    int r, c, k;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++)
            for (m[4 * c + r] = 0, k = 0; k < 4; k++) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
}

static vec4 apply(const double *m, const double *p)
{
    vec4 q;
    q.x = m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12];
    q.y = m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13];
    q.z = m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14];
    q.w = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
    return q;
}

static void rotate(vec3 *a, vec3 *b, double degrees)
{
    double t = degrees * 3.14159265358979323846 / 180;
    vec3 a0 = *a;
    *a = along(vec(cos(t) * a0.x, cos(t) * a0.y, cos(t) * a0.z), sin(t), *b);
    *b = along(vec(cos(t) * b->x, cos(t) * b->y, cos(t) * b->z), -sin(t), a0);
}

static void move(Camera *cam, const c2g_motion *m, vec3 target)
{
    vec3 *axis = m->axis == 'u' ? &cam->u : m->axis == 'v' ? &cam->v : &cam->n;
    if (m->kind == 'r') {
        if (m->axis == 'u') rotate(&cam->v, &cam->n, m->amount);
        if (m->axis == 'v') rotate(&cam->n, &cam->u, m->amount);
        if (m->axis == 'n') rotate(&cam->u, &cam->v, m->amount);
        return;
    }
    cam->eye = along(cam->eye, m->amount, *axis);
    if (m->kind == 'o') {
        cam->n = unit(along(cam->eye, -1, target));
        if (m->axis == 'u') cam->u = unit(cross(cam->v, cam->n)), cam->v = cross(cam->n, cam->u);
        else cam->v = unit(cross(cam->n, cam->u)), cam->u = cross(cam->v, cam->n);
    }
}

int main(int argc, char **argv)
{
    c2g_scene s;
    Camera cam;
    double *tris, view[16] = {0}, proj[16] = {0}, pv[16], lo[3], hi[3], radius = 0, d;
    vec3 centre;
    int count, i, k, t;
    FILE *f;

    if (argc != 3) return 2;
    if (!c2g_read_scene(argv[1], &s) || !(count = load_model(s.model, &tris))) return 1;
    for (k = 0; k < 3; k++) lo[k] = hi[k] = tris[k];
    for (i = 0; i < 9 * count; i++) {
        lo[i % 3] = tris[i] < lo[i % 3] ? tris[i] : lo[i % 3];
        hi[i % 3] = tris[i] > hi[i % 3] ? tris[i] : hi[i % 3];
    }
    for (k = 0; k < 3; k++) radius += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
    radius = sqrt(radius);
    centre = vec((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    cam.fovx = s.hfov, cam.fovy = s.vfov;
    if (s.framed) {
        d = radius / sin((s.hfov < s.vfov ? s.hfov : s.vfov) * 3.14159265358979323846 / 360);
        cam.eye = along(centre, d, vec(0, 0, 1));
        cam.u = vec(1, 0, 0), cam.v = vec(0, 1, 0), cam.n = vec(0, 0, 1);
        cam.znear = s.has_near ? s.znear : (d - radius) / 2;
        cam.zfar = s.has_far ? s.zfar : d + 2 * radius;
    } else {
        cam.eye = vec(s.position[0], s.position[1], s.position[2]);
        cam.u = vec(s.u[0], s.u[1], s.u[2]);
        cam.v = vec(s.v[0], s.v[1], s.v[2]);
        cam.n = vec(s.n[0], s.n[1], s.n[2]);
        cam.znear = s.znear, cam.zfar = s.zfar;
    }
    if (s.has_lookat) centre = vec(s.lookat[0], s.lookat[1], s.lookat[2]);
    for (i = 0; i < s.motion_count; i++) move(&cam, &s.motions[i], centre);

    view[0] = cam.u.x, view[4] = cam.u.y, view[8] = cam.u.z, view[12] = -dot(cam.u, cam.eye);
    view[1] = cam.v.x, view[5] = cam.v.y, view[9] = cam.v.z, view[13] = -dot(cam.v, cam.eye);
    view[2] = cam.n.x, view[6] = cam.n.y, view[10] = cam.n.z, view[14] = -dot(cam.n, cam.eye);
    view[15] = 1;
    proj[0] = 1 / tan(cam.fovx * 3.14159265358979323846 / 360);
    proj[5] = 1 / tan(cam.fovy * 3.14159265358979323846 / 360);
    proj[10] = (cam.zfar + cam.znear) / (cam.znear - cam.zfar);
    proj[14] = 2 * cam.zfar * cam.znear / (cam.znear - cam.zfar);
    proj[11] = -1;
    mul(proj, view, pv);

    if (!(f = fopen(argv[2], "w"))) return 1;                                   /* [trace] */
    c2g_write_header(f);                                                        /* [trace] */
    c2g_write_window(f, s.width, s.height);                                     /* [trace] */
    c2g_write_ortho2d_ndc(f);                                                   /* [trace] */
    {                                                                           /* [trace] */
        double e[3] = {cam.eye.x, cam.eye.y, cam.eye.z}, u[3] = {cam.u.x, cam.u.y, cam.u.z}; /* [trace] */
        double v[3] = {cam.v.x, cam.v.y, cam.v.z}, n[3] = {cam.n.x, cam.n.y, cam.n.z}; /* [trace] */
        c2g_write_camera(f, e, u, v, n, cam.fovx, cam.fovy, cam.znear, cam.zfar); /* [trace] */
    }                                                                           /* [trace] */
    c2g_write_culling_in(f, s.culling, C2G_CULL_IN_NDC);                        /* [trace] */
#ifdef DECLARE_SIMPLE
    c2g_write_clipping(f, C2G_CLIP_SIMPLE);                                     /* [trace: variant] */
#else
    c2g_write_clipping(f, C2G_CLIP_SIMPLE_NEAR_FAR);                            /* [trace] */
#endif
    c2g_write_mode(f, s.mode);                                                  /* [trace] */
    c2g_write_matrix_columns(f, 'M', view);                                     /* [trace] */
    c2g_write_matrix_columns(f, 'P', proj);                                     /* [trace] */
#ifdef IDENTITY_V
    c2g_write_matrix_columns(f, 'V', (double[16]){1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}); /* [trace: variant] */
#endif
    for (t = 0; t < count; t++) {
        vec4 clip[3];
        double ndc[9], area;
        int keep = 1;
        for (i = 0; i < 3; i++) {
            clip[i] = apply(pv, tris + 9 * t + 3 * i);
            keep = keep && clip[i].z >= -clip[i].w && clip[i].z <= clip[i].w;  /* near, far */
        }
        for (i = 0; i < 3 && keep; i++) {
            ndc[3 * i] = clip[i].x / clip[i].w;
            ndc[3 * i + 1] = clip[i].y / clip[i].w;
            ndc[3 * i + 2] = clip[i].z / clip[i].w;
        }
        if (keep && s.culling != C2G_CULL_OFF) {
            area = (ndc[3] - ndc[0]) * (ndc[7] - ndc[1]) - (ndc[6] - ndc[0]) * (ndc[4] - ndc[1]);
            keep = s.culling == C2G_CULL_CCW ? area > 0 : area < 0;
        }
        c2g_write_triangle(f, t, &clip[0].x, keep ? ndc : NULL, 3, 3);         /* [trace] */
    }
    c2g_write_end(f);                                                           /* [trace] */
    fclose(f);                                                                  /* [trace] */
    free(tris);
    c2g_free_scene(&s);
    return 0;
}
