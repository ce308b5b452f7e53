/* c_left_handed.c: a C program with two bugs at two stages. Its camera is left-handed (u = n x v,
 * the camera's right pointing to its left) and its viewport rounds every 2D corner to the
 * nearest whole pixel (an "integer viewport": it fills a pixel grid). y-up window pixels, the
 * assignment's simple clipping, culling by the winding on screen.
 *
 *     c_left_handed SCENE TRACE
 *
 * Lines ending in "[trace]" were added only to write the trace.
 *
 * expect cube_front: differs stage=camera,window names=left_handed unexplained
 * expect far_away_turned: differs stage=camera,window names=left_handed unexplained
 * expect-grade cube: points=0 wireframe=0 solid=0 translation=0 lookat_translation=0 rotation=0 resize=0 synchronized=0
 */
#define CLOSE2GL_TRACE_IMPLEMENTATION /* [trace] */
#include "close2gl_trace.h"
#include "model.h"

#include <math.h>

#define PI 3.14159265358979323846

typedef struct {
    double pos[3], right[3], up[3], back[3]; /* back = n: the camera looks along -back */
    double fovx, fovy, znear, zfar;
} camera_t;

static void cross_into(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* right = back x up, then up = right x back: square to each other */
static void cam_axes_from(camera_t *cam, const double up[3], const double back[3])
{
    double l;
    int i;
    for (i = 0; i < 3; i++) cam->up[i] = up[i], cam->back[i] = back[i];
    cross_into(cam->back, cam->up, cam->right);
    l = sqrt(cam->right[0] * cam->right[0] + cam->right[1] * cam->right[1] + cam->right[2] * cam->right[2]);
    for (i = 0; i < 3; i++) cam->right[i] /= l;
    cross_into(cam->right, cam->back, cam->up);
}

static void cam_turn(double *a, double *b, double deg)
{
    double th = deg * PI / 180, x;
    int i;
    for (i = 0; i < 3; i++) {
        x = a[i];
        a[i] = x * cos(th) + b[i] * sin(th);
        b[i] = b[i] * cos(th) - x * sin(th);
    }
}

static void cam_apply(camera_t *cam, const c2g_motion *m, const double look[3])
{
    double *ax = m->axis == 'u' ? cam->right : m->axis == 'v' ? cam->up : cam->back, b[3], l = 0;
    int i;
    if (m->kind == 'r') {
        if (m->axis == 'u') cam_turn(cam->up, cam->back, m->amount);
        else if (m->axis == 'v') cam_turn(cam->back, cam->right, m->amount);
        else cam_turn(cam->right, cam->up, m->amount);
        return;
    }
    for (i = 0; i < 3; i++) cam->pos[i] += m->amount * ax[i];
    if (m->kind != 'o') return;
    for (i = 0; i < 3; i++) b[i] = cam->pos[i] - look[i], l += b[i] * b[i];
    for (i = 0; i < 3; i++) b[i] /= sqrt(l);
    cam_axes_from(cam, cam->up, b);
}

int main(int argc, char **argv)
{
    c2g_scene s;
    camera_t cam;
    double *tri, lo[3], hi[3], mid[3], rad = 0, dist, mv[16], pr[16] = {0};
    static const double up0[3] = {0, 1, 0}, back0[3] = {0, 0, 1};
    int ntri, i, j, t;
    FILE *tf;

    if (argc != 3) return 2;
    if (!c2g_read_scene(argv[1], &s) || !(ntri = load_model(s.model, &tri))) return 1;
    for (j = 0; j < 3; j++) lo[j] = hi[j] = tri[j];
    for (i = 0; i < 3 * ntri; i++)
        for (j = 0; j < 3; j++) lo[j] = fmin(lo[j], tri[3 * i + j]), hi[j] = fmax(hi[j], tri[3 * i + j]);
    for (j = 0; j < 3; j++) mid[j] = (lo[j] + hi[j]) / 2, rad += (hi[j] - lo[j]) * (hi[j] - lo[j]);
    rad = sqrt(rad) / 2;
    cam.fovx = s.hfov, cam.fovy = s.vfov;
    if (s.framed) {
        dist = rad / sin(fmin(s.hfov, s.vfov) * PI / 360);
        cam_axes_from(&cam, up0, back0);
        for (j = 0; j < 3; j++) cam.pos[j] = mid[j] + dist * back0[j];
        cam.znear = s.has_near ? s.znear : (dist - rad) / 2;
        cam.zfar = s.has_far ? s.zfar : dist + 2 * rad;
    } else {
        cam_axes_from(&cam, s.v, s.n);
        for (j = 0; j < 3; j++) cam.pos[j] = s.position[j];
        cam.znear = s.znear, cam.zfar = s.zfar;
    }
    if (s.has_lookat) memcpy(mid, s.lookat, sizeof mid);
    for (i = 0; i < s.motion_count; i++) cam_apply(&cam, &s.motions[i], mid);

    for (j = 0; j < 3; j++) mv[j] = cam.right[j], mv[4 + j] = cam.up[j], mv[8 + j] = cam.back[j];
    mv[3] = mv[7] = mv[11] = 0;
    for (j = 0; j < 3; j++) {
        mv[3] -= cam.right[j] * cam.pos[j];
        mv[7] -= cam.up[j] * cam.pos[j];
        mv[11] -= cam.back[j] * cam.pos[j];
    }
    mv[12] = mv[13] = mv[14] = 0, mv[15] = 1;
    pr[0] = 1 / tan(cam.fovx * PI / 360), pr[5] = 1 / tan(cam.fovy * PI / 360);
    pr[10] = -(cam.zfar + cam.znear) / (cam.zfar - cam.znear);
    pr[11] = -2 * cam.zfar * cam.znear / (cam.zfar - cam.znear), pr[14] = -1;

    if (!(tf = fopen(argv[2], "w"))) return 1;                                  /* [trace] */
    c2g_write_header(tf);                                                       /* [trace] */
    c2g_write_window(tf, s.width, s.height);                                    /* [trace] */
    c2g_write_camera(tf, cam.pos, cam.right, cam.up, cam.back, cam.fovx, cam.fovy, cam.znear, cam.zfar); /* [trace] */
    c2g_write_culling(tf, s.culling);                                           /* [trace] */
    c2g_write_matrix(tf, 'M', mv);                                              /* [trace] */
    c2g_write_matrix(tf, 'P', pr);                                              /* [trace] */
    c2g_write_mode(tf, s.mode);                                                 /* [trace] */
    {   /* its viewport: (x/w + 1) W/2, (y/w + 1) H/2 */                        /* [trace] */
        c2g_real Vw[16] = {s.width / 2.0, 0, 0, s.width / 2.0, 0, s.height / 2.0, 0, s.height / 2.0, /* [trace] */
                           0, 0, 0.5, 0.5, 0, 0, 0, 1};                         /* [trace] */
        c2g_write_matrix(tf, 'V', Vw);                                          /* [trace] */
    }                                                                           /* [trace] */
    for (t = 0; t < ntri; t++) {
        double eyep[3][4], clip[12], px[6], a;
        int ok = 1;
        for (i = 0; i < 3; i++) {
            const double *p = tri + 9 * t + 3 * i;
            for (j = 0; j < 4; j++) eyep[i][j] = mv[4 * j] * p[0] + mv[4 * j + 1] * p[1] + mv[4 * j + 2] * p[2] + mv[4 * j + 3];
            for (j = 0; j < 4; j++)
                clip[4 * i + j] = pr[4 * j] * eyep[i][0] + pr[4 * j + 1] * eyep[i][1] + pr[4 * j + 2] * eyep[i][2] + pr[4 * j + 3];
            for (j = 0; j < 3; j++) ok = ok && fabs(clip[4 * i + j]) <= clip[4 * i + 3];
        }
        for (i = 0; ok && i < 3; i++) {  /* the integer viewport: whole pixels */
            px[2 * i] = floor((clip[4 * i] / clip[4 * i + 3] + 1) * s.width / 2 + 0.5);
            px[2 * i + 1] = floor((clip[4 * i + 1] / clip[4 * i + 3] + 1) * s.height / 2 + 0.5);
        }
        a = ok ? (px[2] - px[0]) * (px[5] - px[1]) - (px[4] - px[0]) * (px[3] - px[1]) : 0;
        if (ok && s.culling != C2G_CULL_OFF) ok = s.culling == C2G_CULL_CCW ? a > 0 : a < 0;
        c2g_write_triangle(tf, t, clip, ok ? px : NULL, 3, 2);                  /* [trace] */
    }
    c2g_write_end(tf);                                                          /* [trace] */
    fclose(tf);                                                                 /* [trace] */
    free(tri);
    c2g_free_scene(&s);
    return 0;
}
