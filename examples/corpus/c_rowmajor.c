/* c_rowmajor.c: the assignment in plain C, double, matrices as double[4][4] row by row, the 2D
 * output in window pixels with y down (gluOrtho2D(0, W, H, 0)), the assignment's simple clipping
 * (a triangle with any corner outside the view volume is dropped), culling by the winding seen on
 * screen.
 *
 *     c_rowmajor SCENE TRACE
 *
 * Variants (compile-time): -DNEVER_CULLS its culling switch (a key in the real program) is never
 * set from the scene, so it never culls, while the trace declares the scene's culling; -DDROP_SMALL it skips triangles under 1 px^2 ("too small to
 * see"), a rule of its own; -DCULL_SWITCH_MIXUP the culling switch's cases are wired wrong: with
 * counter-clockwise front faces it culls the front faces, with clockwise ones it never culls
 * (one line of the rubric, two mistakes, each on the scenes of its front face).
 *
 * Lines ending in "[trace]" were added only to write the trace.
 *
 * expect cube_front: agree
 * expect knot_turned: agree
 * expect knot_cw: agree
 * expect far_away_turned: agree
 * expect knot_turned -DNEVER_CULLS: differs stage=culling names=never_culls
 * expect knot_cw -DNEVER_CULLS: differs stage=culling names=never_culls
 * expect knot_small -DDROP_SMALL: differs stage=culling unexplained
 * expect knot_turned -DDROP_SMALL: differs stage=culling unexplained
 * expect knot_turned -DCULL_SWITCH_MIXUP: differs stage=culling names=aspect_from_angles,culling_ignores_front_face,culling_inverted,divide_before_clip,fovs_swapped,no_clipping fits=clipping_simple_near_far
 * expect knot_cw -DCULL_SWITCH_MIXUP: differs stage=culling names=never_culls
 * expect-grade cube: 200
 * expect-grade cube -DNEVER_CULLS: culling=12 synchronized=23
 * expect-grade cube -DDROP_SMALL: synchronized=24
 * expect-grade cube -DCULL_SWITCH_MIXUP: culling=12 synchronized=23
 */
#define CLOSE2GL_TRACE_IMPLEMENTATION /* [trace] */
#include "close2gl_trace.h"
#include "model.h"

#include <math.h>

#define PI 3.14159265358979323846

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void turn(double a[3], double b[3], double deg)
{
    /* a, b := a cos + b sin, b cos - a sin: the right-hand rule about the third axis */
    double r = deg * PI / 180, c = cos(r), s = sin(r), k;
    int i;
    for (i = 0; i < 3; i++) {
        k = a[i];
        a[i] = k * c + b[i] * s;
        b[i] = b[i] * c - k * s;
    }
}

static void mult(double a[4][4], double b[4][4], double out[4][4])
{
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            for (out[i][j] = 0, k = 0; k < 4; k++) out[i][j] += a[i][k] * b[k][j];
}

int main(int argc, char **argv)
{
    c2g_scene s;
    double *xyz, c[3], u[3], v[3], n[3], lo[3], hi[3], centre[3], r = 0, d;
    double M[4][4] = {{0}}, P[4][4] = {{0}}, V[4][4] = {{0}}, PM[4][4], znear, zfar, top, right;
    int count, t, i, k, cull_enabled = 0; /* the 'b' key toggles it in the windowed program */
    FILE *out;

    if (argc != 3) return 2;
    if (!c2g_read_scene(argv[1], &s) || !(count = load_model(s.model, &xyz))) return 1;

    for (k = 0; k < 3; k++) lo[k] = hi[k] = xyz[k];
    for (i = 0; i < 3 * count; i++)
        for (k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], xyz[3 * i + k]);
            hi[k] = fmax(hi[k], xyz[3 * i + k]);
        }
    for (k = 0; k < 3; k++) {
        centre[k] = (lo[k] + hi[k]) / 2;
        r += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
    }
    r = sqrt(r);
    if (s.framed) {
        d = r / sin(fmin(s.hfov, s.vfov) * PI / 360);
        for (k = 0; k < 3; k++) c[k] = centre[k], u[k] = v[k] = n[k] = 0;
        c[2] += d, u[0] = v[1] = n[2] = 1;
        znear = s.has_near ? s.znear : (d - r) / 2;
        zfar = s.has_far ? s.zfar : d + 2 * r;
    } else {
        memcpy(c, s.position, sizeof c), memcpy(u, s.u, sizeof u);
        memcpy(v, s.v, sizeof v), memcpy(n, s.n, sizeof n);
        znear = s.znear, zfar = s.zfar;
    }
    for (i = 0; i < s.motion_count; i++) {
        c2g_motion *m = &s.motions[i];
        double *axis = m->axis == 'u' ? u : m->axis == 'v' ? v : n, look[3];
        if (m->kind == 'r' && m->axis == 'u') turn(v, n, m->amount);
        if (m->kind == 'r' && m->axis == 'v') turn(n, u, m->amount);
        if (m->kind == 'r' && m->axis == 'n') turn(u, v, m->amount);
        if (m->kind == 'r') continue;
        for (k = 0; k < 3; k++) c[k] += m->amount * axis[k];
        if (m->kind != 'o') continue;
        for (k = 0; k < 3; k++) look[k] = s.has_lookat ? s.lookat[k] : centre[k];
        for (k = 0; k < 3; k++) n[k] = c[k] - look[k];
        d = sqrt(dot3(n, n));
        for (k = 0; k < 3; k++) n[k] /= d;
        if (m->axis == 'u') {
            cross3(v, n, u), d = sqrt(dot3(u, u));
            for (k = 0; k < 3; k++) u[k] /= d;
            cross3(n, u, v);
        } else {
            cross3(n, u, v), d = sqrt(dot3(v, v));
            for (k = 0; k < 3; k++) v[k] /= d;
            cross3(v, n, u);
        }
    }

    for (k = 0; k < 3; k++) M[0][k] = u[k], M[1][k] = v[k], M[2][k] = n[k];
    M[0][3] = -dot3(c, u), M[1][3] = -dot3(c, v), M[2][3] = -dot3(c, n), M[3][3] = 1;
    top = znear * tan(s.vfov * PI / 360);
    right = znear * tan(s.hfov * PI / 360);
    P[0][0] = znear / right, P[1][1] = znear / top;
    P[2][2] = -(zfar + znear) / (zfar - znear), P[2][3] = -2 * zfar * znear / (zfar - znear);
    P[3][2] = -1;
    V[0][0] = s.width / 2.0, V[0][3] = s.width / 2.0;       /* y down: gluOrtho2D(0, W, H, 0) */
    V[1][1] = -s.height / 2.0, V[1][3] = s.height / 2.0;
    V[2][2] = 0.5, V[2][3] = 0.5, V[3][3] = 1;
    mult(P, M, PM);
#ifndef NEVER_CULLS
    cull_enabled = s.culling != C2G_CULL_OFF;
#endif

    out = fopen(argv[2], "w");                                                  /* [trace] */
    if (!out) return 1;                                                         /* [trace] */
    c2g_write_header(out);                                                      /* [trace] */
    c2g_write_window(out, s.width, s.height);                                   /* [trace] */
    c2g_write_ortho2d(out, 0, s.width, s.height, 0);                            /* [trace] */
    c2g_write_camera(out, c, u, v, n, s.hfov, s.vfov, znear, zfar);             /* [trace] */
    c2g_write_culling(out, s.culling);                                          /* [trace] */
    c2g_write_clipping(out, C2G_CLIP_SIMPLE);                                   /* [trace] */
    c2g_write_mode(out, s.mode);                                                /* [trace] */
    c2g_write_matrix(out, 'M', M[0]);                                           /* [trace] */
    c2g_write_matrix(out, 'P', P[0]);                                           /* [trace] */
    c2g_write_matrix(out, 'V', V[0]);                                           /* [trace] */
    for (t = 0; t < count; t++) {
        double clip[12], win[6], area = 0;
        int drop = 0;
        for (i = 0; i < 3; i++) {
            double *p = xyz + 9 * t + 3 * i, *q = clip + 4 * i;
            for (k = 0; k < 4; k++) q[k] = PM[k][0] * p[0] + PM[k][1] * p[1] + PM[k][2] * p[2] + PM[k][3];
            drop |= !(fabs(q[0]) <= q[3] && fabs(q[1]) <= q[3] && fabs(q[2]) <= q[3]);
        }
        for (i = 0; i < 3 && !drop; i++) {
            win[2 * i] = V[0][0] * clip[4 * i] / clip[4 * i + 3] + V[0][3];
            win[2 * i + 1] = V[1][1] * clip[4 * i + 1] / clip[4 * i + 3] + V[1][3];
        }
        if (!drop) area = (win[2] - win[0]) * (win[5] - win[1]) - (win[4] - win[0]) * (win[3] - win[1]);
        /* y down: a triangle counter-clockwise on screen has a negative area in these numbers */
#ifdef CULL_SWITCH_MIXUP
        if (cull_enabled && (s.culling == C2G_CULL_CCW ? area <= 0 : 0)) drop = 1;
#else
        if (cull_enabled && (s.culling == C2G_CULL_CCW ? area >= 0 : area <= 0)) drop = 1;
#endif
#ifdef DROP_SMALL
        if (fabs(area) / 2 < 1) drop = 1;
#endif
        c2g_write_triangle(out, t, clip, drop ? NULL : win, 3, 2);              /* [trace] */
    }
    c2g_write_end(out);                                                         /* [trace] */
    fclose(out);                                                                /* [trace] */
    free(xyz);
    c2g_free_scene(&s);
    return 0;
}
