/* model.h: the corpus programs' shared minimal model loader (the pipeline math is what differs
 * between them, not the reading of files). C99 and C++.
 *
 *     double *xyz; int n = load_model(path, &xyz);   // n triangles, xyz[9*t + 3*corner + axis]
 *
 * Reads the course's .in format (the v0, v1, v2 lines of each triangle; everything else is
 * skipped) and Wavefront .obj (v and f lines; a polygon becomes a fan from its first corner,
 * negative indices count from the end). Returns the triangle count, or 0 after printing
 * "path:line: ..." on stderr. Triangles keep the file's order: t is the trace's index. */
#ifndef CORPUS_MODEL_H
#define CORPUS_MODEL_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int model_grow(double **a, int *cap, int need)
{
    double *grown;
    if (need <= *cap) return 1;
    *cap = need * 2;
    grown = (double *)realloc(*a, (size_t)*cap * sizeof **a);
    if (!grown) return 0;
    *a = grown;
    return 1;
}

/* One OBJ corner "7", "7/2", "7//3" or "7/2/3": its 0-based vertex, or -1. */
static int model_obj_corner(const char *s, int vertices)
{
    char *end;
    long i = strtol(s, &end, 10);
    if (end == s || (*end != '\0' && *end != '/')) return -1;
    if (i < 0) i += vertices + 1;
    return i >= 1 && i <= vertices ? (int)i - 1 : -1;
}

static int model_line(const char *path, int number, const char *what)
{
    fprintf(stderr, "%s:%d: expected %s\n", path, number, what);
    return 0;
}

static int load_model(const char *path, double **xyz_out)
{
    FILE *f = fopen(path, "r");
    char line[4096], *field[32];
    double *v = NULL, *xyz = NULL, p[3];
    int nv = 0, capv = 0, nt = 0, capt = 0, number = 0, obj, k, ok = 1;
    size_t len = strlen(path);
    if (!f) {
        perror(path);
        return 0;
    }
    obj = len > 4 && (strcmp(path + len - 4, ".obj") == 0 || strcmp(path + len - 4, ".OBJ") == 0);
    while (ok && fgets(line, sizeof line, f)) {
        int count = 0;
        char *s = strtok(line, " \t\r\n");
        number++;
        for (; s && count < 32; s = strtok(NULL, " \t\r\n")) field[count++] = s;
        if (count == 0) continue;
        if (!obj && field[0][0] == 'v' && strchr("012", field[0][1]) && field[0][2] == '\0') {
            ok = count >= 4 && model_grow(&xyz, &capt, 9 * nt + 9);
            for (k = 0; ok && k < 3; k++) xyz[9 * nt + 3 * (field[0][1] - '0') + k] = atof(field[1 + k]);
            if (!ok) model_line(path, number, "'vK x y z ...'");
            if (field[0][1] == '2') nt++;
        } else if (obj && strcmp(field[0], "v") == 0) {
            ok = count >= 4 && model_grow(&v, &capv, 3 * nv + 3);
            for (k = 0; ok && k < 3; k++) v[3 * nv + k] = atof(field[1 + k]);
            if (!ok) model_line(path, number, "'v x y z'");
            nv++;
        } else if (obj && strcmp(field[0], "f") == 0) {
            int first = model_obj_corner(field[1], nv), i;
            for (i = 2; ok && i + 1 < count; i++) {
                int b = model_obj_corner(field[i], nv), c = model_obj_corner(field[i + 1], nv);
                ok = first >= 0 && b >= 0 && c >= 0 && model_grow(&xyz, &capt, 9 * nt + 9);
                if (!ok) break;
                memcpy(xyz + 9 * nt, v + 3 * first, sizeof p);
                memcpy(xyz + 9 * nt + 3, v + 3 * b, sizeof p);
                memcpy(xyz + 9 * nt + 6, v + 3 * c, sizeof p);
                nt++;
            }
            if (!ok || count < 4) ok = model_line(path, number, "'f' with 3 or more known vertices");
        }
    }
    fclose(f);
    free(v);
    if (ok && nt == 0) ok = model_line(path, number, "at least one triangle");
    if (!ok) {
        free(xyz);
        return 0;
    }
    *xyz_out = xyz;
    return nt;
}

#endif
