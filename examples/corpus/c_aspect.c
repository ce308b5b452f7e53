/* c_aspect.c: a float32 C program with gluPerspective's habit: P is built from the vertical field
 * of view and the window's aspect (right = top * W / H), whatever horizontal field of view the
 * scene asks. With hfov = vfov = 60 in 640x480 its horizontal field of view is 75.18 degrees.
 * 2D output in window pixels, y up (gluOrtho2D(0, W, 0, H)); the assignment's simple clipping;
 * culling by the winding on screen.
 *
 *     c_aspect SCENE TRACE
 *
 * As it is, it writes the scene's hfov in its trace: its P[0][0] is 0.75 of the P that hfov
 * gives. Variant: -DWRITE_USED_HFOV writes the horizontal field of view it really used,
 * 2 atan(W/H tan(vfov/2)): a different frame, but a true trace of it.
 *
 * Lines ending in "[trace]" were added only to write the trace.
 *
 * expect cube_front: differs stage=P unexplained
 * expect knot_turned: differs stage=P unexplained
 * expect cube_front -DWRITE_USED_HFOV: agree
 * expect knot_turned -DWRITE_USED_HFOV: agree
 * expect-grade cube: points=0 wireframe=0 solid=0 hfov=0 synchronized=0
 * expect-grade cube -DWRITE_USED_HFOV: points=0 wireframe=0 solid=0 hfov=0 synchronized=0
 */
#define CLOSE2GL_FLOAT                /* [trace] */
#define CLOSE2GL_TRACE_IMPLEMENTATION /* [trace] */
#include "close2gl_trace.h"
#include "model.h"

#include <math.h>

#define DEG2RAD 0.017453292519943295f

static float eye[3], U[3], Vv[3], N[3], zNear, zFar;

static float dot(const float *a, const float *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void spin(float *a, float *b, float degrees) /* a toward b, right-hand rule */
{
    float c = cosf(degrees * DEG2RAD), s = sinf(degrees * DEG2RAD), t;
    int i;
    for (i = 0; i < 3; i++) t = a[i], a[i] = c * t + s * b[i], b[i] = c * b[i] - s * t;
}

static void normalize(float *a)
{
    float l = sqrtf(dot(a, a));
    a[0] /= l, a[1] /= l, a[2] /= l;
}

static void cross(const float *a, const float *b, float *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1], out[1] = a[2] * b[0] - a[0] * b[2], out[2] = a[0] * b[1] - a[1] * b[0];
}

/* gluPerspective: f = cot(fovy/2); the x scale is f / aspect */
static void perspective(float fovy, float aspect, float n, float f, float P[4][4])
{
    float c = 1 / tanf(fovy * DEG2RAD / 2);
    memset(P, 0, 16 * sizeof(float));
    P[0][0] = c / aspect, P[1][1] = c;
    P[2][2] = (f + n) / (n - f), P[2][3] = 2 * f * n / (n - f), P[3][2] = -1;
}

static void lookat_camera(const float *centre, float radius, const c2g_scene *s)
{
    float d = radius / sinf((s->hfov < s->vfov ? s->hfov : s->vfov) * DEG2RAD / 2);
    int i;
    for (i = 0; i < 3; i++) eye[i] = centre[i], U[i] = Vv[i] = N[i] = 0;
    eye[2] += d, U[0] = Vv[1] = N[2] = 1;
    zNear = s->has_near ? s->znear : (d - radius) / 2;
    zFar = s->has_far ? s->zfar : d + 2 * radius;
}

static void motions(const c2g_scene *s, const float *centre)
{
    int i, k;
    for (i = 0; i < s->motion_count; i++) {
        const c2g_motion *m = &s->motions[i];
        float *axis = m->axis == 'u' ? U : m->axis == 'v' ? Vv : N;
        if (m->kind == 'r') {
            spin(m->axis == 'u' ? Vv : m->axis == 'v' ? N : U, m->axis == 'u' ? N : m->axis == 'v' ? U : Vv, m->amount);
            continue;
        }
        for (k = 0; k < 3; k++) eye[k] += m->amount * axis[k];
        if (m->kind == 'm') continue;
        for (k = 0; k < 3; k++) N[k] = eye[k] - (s->has_lookat ? s->lookat[k] : centre[k]);
        normalize(N);
        if (m->axis == 'u') cross(Vv, N, U), normalize(U), cross(N, U, Vv);
        else cross(N, U, Vv), normalize(Vv), cross(Vv, N, U);
    }
}

int main(int argc, char **argv)
{
    c2g_scene s;
    double *tris;
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f}, centre[3], radius = 0;
    float MV[4][4] = {{0}}, P[4][4], PM[4][4] = {{0}}, aspect, hfov;
    int count, i, j, k, t;
    FILE *out;

    if (argc != 3) return 2;
    if (!c2g_read_scene(argv[1], &s) || !(count = load_model(s.model, &tris))) return 1;
    for (i = 0; i < 9 * count; i++) {
        lo[i % 3] = fminf(lo[i % 3], (float)tris[i]);
        hi[i % 3] = fmaxf(hi[i % 3], (float)tris[i]);
    }
    for (k = 0; k < 3; k++) centre[k] = (lo[k] + hi[k]) / 2, radius += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
    radius = sqrtf(radius);
    if (s.framed) {
        lookat_camera(centre, radius, &s);
    } else {
        memcpy(eye, s.position, sizeof eye), memcpy(U, s.u, sizeof U);
        memcpy(Vv, s.v, sizeof Vv), memcpy(N, s.n, sizeof N);
        zNear = s.znear, zFar = s.zfar;
    }
    motions(&s, centre);

    for (k = 0; k < 3; k++) MV[0][k] = U[k], MV[1][k] = Vv[k], MV[2][k] = N[k];
    MV[0][3] = -dot(U, eye), MV[1][3] = -dot(Vv, eye), MV[2][3] = -dot(N, eye), MV[3][3] = 1;
    aspect = (float)s.width / (float)s.height;
    perspective(s.vfov, aspect, zNear, zFar, P);
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (k = 0; k < 4; k++) PM[i][j] += P[i][k] * MV[k][j];
    hfov = s.hfov;
#ifdef WRITE_USED_HFOV
    hfov = 2 * atanf(aspect * tanf(s.vfov * DEG2RAD / 2)) / DEG2RAD;
#endif

    out = fopen(argv[2], "w");                                                  /* [trace] */
    if (!out) return 1;                                                         /* [trace] */
    c2g_write_header(out);                                                      /* [trace] */
    c2g_write_window(out, s.width, s.height);                                   /* [trace] */
    c2g_write_camera(out, eye, U, Vv, N, hfov, s.vfov, zNear, zFar);            /* [trace] */
    c2g_write_culling(out, s.culling);                                          /* [trace] */
    c2g_write_matrix(out, 'M', &MV[0][0]);                                      /* [trace] */
    c2g_write_matrix(out, 'P', &P[0][0]);                                       /* [trace] */
    c2g_write_mode(out, s.mode);                                                /* [trace] */
    {   /* its viewport: (x/w + 1) W/2, (y/w + 1) H/2 */                        /* [trace] */
        c2g_real Vw[16] = {s.width / 2.0, 0, 0, s.width / 2.0, 0, s.height / 2.0, 0, s.height / 2.0, /* [trace] */
                           0, 0, 0.5, 0.5, 0, 0, 0, 1};                         /* [trace] */
        c2g_write_matrix(out, 'V', Vw);                                         /* [trace] */
    }                                                                           /* [trace] */
    for (t = 0; t < count; t++) {
        float c[3][4], xy[6], area;
        int in = 1;
        for (i = 0; i < 3; i++) {
            for (k = 0; k < 4; k++)
                c[i][k] = PM[k][0] * (float)tris[9 * t + 3 * i] + PM[k][1] * (float)tris[9 * t + 3 * i + 1]
                          + PM[k][2] * (float)tris[9 * t + 3 * i + 2] + PM[k][3];
            for (k = 0; k < 3; k++) in = in && c[i][k] >= -c[i][3] && c[i][k] <= c[i][3];
        }
        for (i = 0; i < 3 && in; i++) {
            xy[2 * i] = (c[i][0] / c[i][3] + 1) * s.width / 2;
            xy[2 * i + 1] = (c[i][1] / c[i][3] + 1) * s.height / 2;
        }
        area = in ? (xy[2] - xy[0]) * (xy[5] - xy[1]) - (xy[4] - xy[0]) * (xy[3] - xy[1]) : 0;
        if (s.culling == C2G_CULL_CCW && area <= 0) in = 0;
        if (s.culling == C2G_CULL_CW && area >= 0) in = 0;
        c2g_write_triangle(out, t, &c[0][0], in ? xy : NULL, 3, 2);            /* [trace] */
    }
    c2g_write_end(out);                                                         /* [trace] */
    fclose(out);                                                                /* [trace] */
    free(tris);
    c2g_free_scene(&s);
    return 0;
}
