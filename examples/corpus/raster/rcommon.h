/* rcommon.h: what the raster corpus's C and C++ programs share, because it is not what differs
 * between students' rasterizers: reading the model (positions, vertex normals, s t) and the
 * first assignment's camera (framing, the scene's moves, M and P), which every student carries
 * over from the first assignment. C99 and C++, double; include after close2gl_trace.h.
 *
 *     rc_mesh m; if (!rc_load(path, &m)) return 1;   // m.tri[t]: p[3][3], n[3][3], uv[3][2]
 *     double M[16], P[16]; rc_camera(&scene, &m, M, P);   // row by row
 *
 * The .in format (v0 v1 v2 lines: x y z nx ny nz material [s t]) and Wavefront OBJ (v, vt, vn,
 * f; polygons as fans; a corner without vn takes the face's normal; textured when every corner
 * has vt). Triangles keep the file's order: t is the trace's index. */
#ifndef RC_COMMON_H
#define RC_COMMON_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { double p[3][3], n[3][3], uv[3][2]; } rc_tri;
typedef struct { rc_tri *tri; int count, textured; } rc_mesh;

/* The lecture's lighting constants (close2gl's Lighting::default). */
static const double RC_IA[3] = {0.3, 1, 0.3}, RC_IL[3] = {1, 1, 1};
static const double RC_KA = 0.3, RC_KD = 0.8, RC_KS = 0.5, RC_SHININESS = 10;
static const double RC_ATT[3] = {0.01, 0.001, 0};

static int rc_push(rc_mesh *m, int *cap, const rc_tri *t)
{
    if (m->count == *cap) {
        rc_tri *grown;
        *cap = *cap ? 2 * *cap : 64;
        grown = (rc_tri *)realloc(m->tri, (size_t)*cap * sizeof *grown);
        if (!grown) return 0;
        m->tri = grown;
    }
    m->tri[m->count++] = *t;
    return 1;
}

static int rc_grow(double **a, int *cap, int need)
{
    double *grown;
    if (need <= *cap) return 1;
    *cap = 2 * need;
    grown = (double *)realloc(*a, (size_t)*cap * sizeof **a);
    if (!grown) return 0;
    *a = grown;
    return 1;
}

static int rc_load(const char *path, rc_mesh *m)
{
    FILE *f = fopen(path, "r");
    char line[4096], *field[32];
    double *v[3] = {NULL, NULL, NULL};
    int count[3] = {0, 0, 0}, cap[3] = {0, 0, 0}, tcap = 0, number = 0, ok = 1, obj, textured = 1;
    size_t len = strlen(path);
    rc_tri t;
    memset(m, 0, sizeof *m);
    memset(&t, 0, sizeof t);
    if (!f) {
        perror(path);
        return 0;
    }
    obj = len > 4 && (strcmp(path + len - 4, ".obj") == 0 || strcmp(path + len - 4, ".OBJ") == 0);
    while (ok && fgets(line, sizeof line, f)) {
        int n = 0, k;
        char *s = strtok(line, " \t\r\n");
        number++;
        for (; s && n < 32; s = strtok(NULL, " \t\r\n")) field[n++] = s;
        if (n == 0) continue;
        if (!obj && !strcmp(field[0], "Texture") && n == 3) m->textured = !strcmp(field[2], "YES");
        if (!obj && field[0][0] == 'v' && field[0][1] >= '0' && field[0][1] <= '2' && !field[0][2]) {
            int c = field[0][1] - '0';
            ok = n >= (m->textured ? 10 : 8);
            for (k = 0; ok && k < 3; k++) {
                t.p[c][k] = atof(field[1 + k]);
                t.n[c][k] = atof(field[4 + k]);
            }
            t.uv[c][0] = m->textured && ok ? atof(field[8]) : 0;
            t.uv[c][1] = m->textured && ok ? atof(field[9]) : 0;
            if (ok && c == 2) ok = rc_push(m, &tcap, &t);
        } else if (obj && (!strcmp(field[0], "v") || !strcmp(field[0], "vt") || !strcmp(field[0], "vn"))) {
            int kind = field[0][1] == 't' ? 1 : field[0][1] == 'n' ? 2 : 0;
            ok = n >= (kind == 1 ? 3 : 4) && rc_grow(&v[kind], &cap[kind], 3 * count[kind] + 3);
            for (k = 0; ok && k < (kind == 1 ? 2 : 3); k++) v[kind][3 * count[kind] + k] = atof(field[1 + k]);
            count[kind]++;
        } else if (obj && !strcmp(field[0], "f")) {
            int idx[32][3], i, c;
            ok = n >= 4;
            for (i = 0; ok && i + 1 < n; i++) {
                char *p = field[1 + i];
                for (c = 0; c < 3; c++) {
                    char *end;
                    long j = strtol(p, &end, 10);
                    idx[i][c] = end == p ? -1 : (int)(j < 0 ? j + count[c] : j - 1);
                    if (end != p && (idx[i][c] < 0 || idx[i][c] >= count[c])) ok = 0;
                    p = *end == '/' ? end + 1 : end;
                    if (*end != '/') {
                        for (c++; c < 3; c++) idx[i][c] = -1;
                        break;
                    }
                }
                ok = ok && idx[i][0] >= 0;
                textured &= idx[i][1] >= 0;
            }
            for (i = 2; ok && i + 1 < n; i++) {
                int corner[3] = {0, i - 1, i};
                double e1[3], e2[3], face[3], l;
                for (c = 0; c < 3; c++) {
                    const int *at = idx[corner[c]];
                    for (k = 0; k < 3; k++) t.p[c][k] = v[0][3 * at[0] + k];
                    for (k = 0; k < 2; k++) t.uv[c][k] = at[1] >= 0 ? v[1][3 * at[1] + k] : 0;
                }
                for (k = 0; k < 3; k++) e1[k] = t.p[1][k] - t.p[0][k], e2[k] = t.p[2][k] - t.p[0][k];
                face[0] = e1[1] * e2[2] - e1[2] * e2[1], face[1] = e1[2] * e2[0] - e1[0] * e2[2];
                face[2] = e1[0] * e2[1] - e1[1] * e2[0];
                l = sqrt(face[0] * face[0] + face[1] * face[1] + face[2] * face[2]);
                for (c = 0; c < 3; c++)
                    for (k = 0; k < 3; k++)
                        t.n[c][k] = idx[corner[c]][2] >= 0 ? v[2][3 * idx[corner[c]][2] + k]
                                                           : face[k] / (l > 0 ? l : 1);
                ok = rc_push(m, &tcap, &t);
            }
        }
        if (!ok) fprintf(stderr, "%s:%d: expected a model line\n", path, number);
    }
    fclose(f);
    if (obj) m->textured = textured && m->count > 0;
    free(v[0]), free(v[1]), free(v[2]);
    if (ok && m->count == 0) fprintf(stderr, "%s: expected at least one triangle\n", path), ok = 0;
    return ok;
}

/* ---- the first assignment's camera ---------------------------------------------------------- */

static double rc_dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void rc_cross(const double *a, const double *b, double *o)
{
    double r[3];
    r[0] = a[1] * b[2] - a[2] * b[1], r[1] = a[2] * b[0] - a[0] * b[2], r[2] = a[0] * b[1] - a[1] * b[0];
    memcpy(o, r, sizeof r);
}
static void rc_unit(double *a)
{
    double l = sqrt(rc_dot(a, a));
    a[0] /= l, a[1] /= l, a[2] /= l;
}

static void rc_bounds(const rc_mesh *m, double centre[3], double *radius)
{
    double lo[3], hi[3], d[3];
    int i, c, k;
    memcpy(lo, m->tri[0].p[0], sizeof lo), memcpy(hi, lo, sizeof hi);
    for (i = 0; i < m->count; i++)
        for (c = 0; c < 3; c++)
            for (k = 0; k < 3; k++) {
                double x = m->tri[i].p[c][k];
                lo[k] = x < lo[k] ? x : lo[k], hi[k] = x > hi[k] ? x : hi[k];
            }
    for (k = 0; k < 3; k++) centre[k] = 0.5 * (lo[k] + hi[k]), d[k] = hi[k] - lo[k];
    *radius = 0.5 * sqrt(rc_dot(d, d));
}

/* M and P (row by row) for the scene's camera after its moves. */
static void rc_camera(const c2g_scene *s, const rc_mesh *m, double M[16], double P[16])
{
    double c[3], u[3], v[3], n[3], centre[3], look[3], r, znear, zfar, top, right;
    int i, k;
    rc_bounds(m, centre, &r);
    if (s->framed) {
        double d;
        if (!(r > 0)) r = 1;
        d = r / sin((s->hfov < s->vfov ? s->hfov : s->vfov) * 3.14159265358979323846 / 360);
        c[0] = centre[0], c[1] = centre[1], c[2] = centre[2] + d;
        u[0] = 1, u[1] = 0, u[2] = 0, v[0] = 0, v[1] = 1, v[2] = 0, n[0] = 0, n[1] = 0, n[2] = 1;
        znear = s->has_near ? s->znear : 0.5 * (d - r);
        if (!(znear > 0)) znear = 0.01 * r;
        zfar = s->has_far ? s->zfar : d + 2 * r;
        if (zfar <= znear) {
            if (s->has_near) zfar = znear + 2 * r;
            else znear = 0.01 * zfar;
        }
    } else {
        for (k = 0; k < 3; k++) c[k] = s->position[k], u[k] = s->u[k], v[k] = s->v[k], n[k] = s->n[k];
        znear = s->znear, zfar = s->zfar;
    }
    for (k = 0; k < 3; k++) look[k] = s->has_lookat ? s->lookat[k] : centre[k];
    for (i = 0; i < s->motion_count; i++) {
        const c2g_motion *mo = &s->motions[i];
        double *axis = mo->axis == 'u' ? u : mo->axis == 'v' ? v : n, a = mo->amount * 3.14159265358979323846 / 180;
        double cs = cos(a), sn = sin(a), u0[3], v0[3], n0[3];
        memcpy(u0, u, sizeof u0), memcpy(v0, v, sizeof v0), memcpy(n0, n, sizeof n0);
        if (mo->kind == 'm') {
            for (k = 0; k < 3; k++) c[k] += axis[k] * mo->amount;
        } else if (mo->kind == 'r') {
            for (k = 0; k < 3; k++) {
                if (mo->axis == 'u') v[k] = v0[k] * cs + n0[k] * sn, n[k] = n0[k] * cs - v0[k] * sn;
                else if (mo->axis == 'v') n[k] = n0[k] * cs + u0[k] * sn, u[k] = u0[k] * cs - n0[k] * sn;
                else u[k] = u0[k] * cs + v0[k] * sn, v[k] = v0[k] * cs - u0[k] * sn;
            }
        } else {
            for (k = 0; k < 3; k++) c[k] += axis[k] * mo->amount, n[k] = c[k] - look[k];
            rc_unit(n);
            if (mo->axis == 'u') rc_cross(v, n, u), rc_unit(u), rc_cross(n, u, v);
            else rc_cross(n, u, v), rc_unit(v), rc_cross(v, n, u);
        }
    }
    for (k = 0; k < 3; k++) M[k] = u[k], M[4 + k] = v[k], M[8 + k] = n[k];
    M[3] = -rc_dot(c, u), M[7] = -rc_dot(c, v), M[11] = -rc_dot(c, n);
    M[12] = M[13] = M[14] = 0, M[15] = 1;
    top = znear * tan(s->vfov * 3.14159265358979323846 / 360);
    right = znear * tan(s->hfov * 3.14159265358979323846 / 360);
    memset(P, 0, 16 * sizeof *P);
    P[0] = znear / right, P[5] = znear / top;
    P[10] = -(zfar + znear) / (zfar - znear), P[11] = -2 * zfar * znear / (zfar - znear), P[14] = -1;
}

/* The file name of a path (the trace names its buffers relative to its own folder). */
static const char *rc_base(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

#endif
