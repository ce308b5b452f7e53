/* close2gl_trace.h: read a close2gl scene file and write a close2gl trace (format version 1).
 *
 * Header-only C99 (it compiles as C++ too). In exactly one .c or .cpp file write
 *
 *     #define CLOSE2GL_TRACE_IMPLEMENTATION
 *     #include "close2gl_trace.h"
 *
 * and include it plainly everywhere else. Numbers are c2g_real: double, or float when compiled
 * with -DCLOSE2GL_FLOAT (use that if your program computes in float).
 *
 * Reading a scene, with every rule of the format checked (messages go to stderr, as close2gl
 * writes them: "view.scene:5: expected 'move u|v|n D', found 'move w 1'"):
 *
 *     c2g_scene scene;
 *     if (!c2g_read_scene("view.scene", &scene)) return 1;
 *     ... load scene.model, set the camera, apply scene.motions[0 .. scene.motion_count - 1] ...
 *     c2g_free_scene(&scene);
 *
 * A scene for the rasterizer assignment may also give shading, color, background, light,
 * texture and filter (docs/raster-trace-format.md): scene.shading, .color, .background, .light,
 * .has_texture, .texture (resolved like the model) and .filter, with their defaults otherwise.
 *
 * Writing a trace: open a FILE, call c2g_write_header, then the c2g_write_* of whatever your
 * program computes (camera and window are required), then c2g_write_end. Numbers are printed with
 * %.17g (double) or %.9g (float), enough digits to read back the very same value. In the loop
 * that draws, one call per mesh triangle writes its clip coordinates and what was drawn of it:
 *
 *     c2g_write_triangle(f, t, clip, drawn ? corners : NULL, 3, 2);
 *
 * c2g_write_end writes `drawn N` (how many tri and poly lines the trace has) before `end`, so that
 * a program that drew nothing says so. It counts the lines written to the FILE that the last
 * c2g_write_header started: one trace at a time (a second header started before the first trace's
 * end takes the count over, and the first trace then ends without a `drawn` line rather than
 * with a wrong one).
 *
 * Both use the C library's number formats, which follow the locale: if your program (or its GUI
 * toolkit) calls setlocale, keep LC_NUMERIC at "C" or "0.5" becomes "0,5".
 */
#ifndef CLOSE2GL_TRACE_H
#define CLOSE2GL_TRACE_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifdef CLOSE2GL_FLOAT
typedef float c2g_real;
#define C2G_FMT " %.9g"
#else
typedef double c2g_real;
#define C2G_FMT " %.17g"
#endif

enum { C2G_CULL_OFF, C2G_CULL_CCW, C2G_CULL_CW };
/* The last two are for trace lines only: near and far by the program, x and y by the 2D
 * rasteriser (`clipping simple near_far`, `clipping full near_far`). */
enum { C2G_CLIP_SIMPLE, C2G_CLIP_FULL, C2G_CLIP_NONE, C2G_CLIP_SIMPLE_NEAR_FAR,
       C2G_CLIP_FULL_NEAR_FAR };
/* Where the program tests the winding: as seen on screen (version 1's plain `culling ccw`), in
 * NDC before V, or in its 2D output's own numbers. */
enum { C2G_CULL_ON_SCREEN, C2G_CULL_IN_NDC, C2G_CULL_IN_WINDOW };
enum { C2G_MODE_POINTS, C2G_MODE_WIREFRAME, C2G_MODE_SOLID };
/* The rasterizer assignment's scene lines (docs/raster-trace-format.md). */
enum { C2G_SHADING_NONE, C2G_SHADING_GOURAUD_AD, C2G_SHADING_GOURAUD_ADS, C2G_SHADING_PHONG };
enum { C2G_FILTER_NEAREST, C2G_FILTER_BILINEAR, C2G_FILTER_TRILINEAR };

/* One camera motion of a scene, to apply in order: `move`, `rotate` or `orbit`. */
typedef struct {
    char kind;       /* 'm' move, 'r' rotate, 'o' orbit */
    char axis;       /* 'u', 'v' or 'n' (orbit: 'u' or 'v') */
    c2g_real amount; /* world units (move, orbit) or degrees (rotate) */
} c2g_motion;

/* A scene file. (The clipping planes are znear and zfar: windows.h defines near and far.) */
typedef struct {
    char model[1024];      /* the model's path, resolved against the scene file's folder */
    int width, height;     /* window W H */
    int framed;            /* 1: `camera framed`; 0: the eight camera lines were given */
    c2g_real position[3], u[3], v[3], n[3]; /* the camera (all 0 when framed) */
    c2g_real hfov, vfov;   /* degrees (framed and not given: 60) */
    c2g_real znear, zfar;  /* framed and not given: 0, with has_near / has_far 0 */
    int has_near, has_far;
    int culling;           /* C2G_CULL_OFF (default), C2G_CULL_CCW, C2G_CULL_CW */
    int clipping;          /* C2G_CLIP_SIMPLE (default), C2G_CLIP_FULL, C2G_CLIP_NONE */
    int mode;              /* C2G_MODE_SOLID (default), C2G_MODE_POINTS, C2G_MODE_WIREFRAME */
    int has_lookat;        /* 0: orbit around the model's bounding-box centre */
    c2g_real lookat[3];
    int motion_count;
    c2g_motion *motions;   /* malloc'ed; c2g_free_scene frees it */
    /* The rasterizer assignment's lines (absent from a geometry scene: the defaults). */
    int shading;           /* C2G_SHADING_NONE (default), _GOURAUD_AD, _GOURAUD_ADS, _PHONG */
    c2g_real color[3];     /* the model's colour, each in [0, 1] (default 1 1 1) */
    c2g_real background[3];/* the clear colour (default 0 0 0) */
    c2g_real light[3];     /* the light's world position (default 10 10 3) */
    int has_texture;       /* 0: no `texture` line */
    char texture[1024];    /* the PPM's path, resolved against the scene file's folder */
    int filter;            /* C2G_FILTER_NEAREST (default), _BILINEAR, _TRILINEAR */
} c2g_scene;

/* Reads a scene file: 1, or 0 after printing why on stderr ("file:line: expected ..., found ...").
 * (One rule is not checked: that the file is UTF-8.) */
int c2g_read_scene(const char *path, c2g_scene *scene);
void c2g_free_scene(c2g_scene *scene);

/* Trace lines, in the order a trace usually has them. Vectors are 3 numbers. */
void c2g_write_header(FILE *f);                         /* close2gl-trace 1 */
void c2g_write_model(FILE *f, const char *name);
void c2g_write_triangles(FILE *f, int count);
void c2g_write_window(FILE *f, int width, int height);
void c2g_write_ortho2d(FILE *f, c2g_real left, c2g_real right, c2g_real bottom, c2g_real top);
/* NDC output (the GPU does the viewport): ortho2d -1 1 -1 1. */
void c2g_write_ortho2d_ndc(FILE *f);
void c2g_write_camera(FILE *f, const c2g_real position[3], const c2g_real u[3],
                      const c2g_real v[3], const c2g_real n[3], c2g_real hfov, c2g_real vfov,
                      c2g_real znear, c2g_real zfar); /* the eight camera lines */
void c2g_write_culling(FILE *f, int culling);           /* C2G_CULL_... */
/* culling C2G_CULL_..., tested in space C2G_CULL_IN_NDC or C2G_CULL_IN_WINDOW ("culling ccw ndc"). */
void c2g_write_culling_in(FILE *f, int culling, int space);
void c2g_write_clipping(FILE *f, int clipping);         /* C2G_CLIP_... */
void c2g_write_mode(FILE *f, int mode);                 /* C2G_MODE_... */
/* which is 'M', 'P' or 'V'. m is row by row: m[4*row + column]. */
void c2g_write_matrix(FILE *f, char which, const c2g_real *m);
/* The same for a column-major array, as OpenGL and glm store matrices: m[4*column + row]. */
void c2g_write_matrix_columns(FILE *f, char which, const c2g_real *m);
/* The model matrix applied to the file's vertices before M (`matrix model`), rows or columns. */
void c2g_write_model_matrix(FILE *f, const c2g_real *m);
void c2g_write_model_matrix_columns(FILE *f, const c2g_real *m);
/* Mesh triangle t (0-based, in the model file's order) in clip coordinates: x y z w per corner. */
void c2g_write_clip(FILE *f, int t, const c2g_real *clip);
/* A drawn 2D triangle for mesh triangle t: dims 2 (x y per corner) or 3 (x y and NDC depth z). */
void c2g_write_tri(FILE *f, int t, const c2g_real *corners, int dims);
/* A drawn polygon of k >= 3 corners for mesh triangle t (what full clipping leaves). */
void c2g_write_poly(FILE *f, int t, int k, const c2g_real *corners, int dims);
/* Mesh triangle t in one call: its `clip` line when clip (x y z w per corner) is not NULL, then,
 * when corners is not NULL and k >= 3, what was drawn of it: a `tri` line for k = 3 corners, a
 * `poly` line for more. dims 2 (x y) or 3 (x y and NDC depth). corners NULL: not drawn. */
void c2g_write_triangle(FILE *f, int t, const c2g_real *clip, const c2g_real *corners, int k,
                        int dims);
/* `drawn N` when the trace has clip, tri or poly lines (a program that writes only matrices
 * says nothing about its 2D output), then `end`: nothing may follow. */
void c2g_write_end(FILE *f);

/* Two helpers for your own loaders. c2g_split cuts line into fields at runs of spaces and tabs
 * (writing '\0's into it); returns the number of fields, at most max + 1 ("too many").
 * c2g_parse_real takes a whole field written as %d, %f, %e or %g print numbers, and finite:
 * returns 1 and stores it, or 0 (for "abc", "1.5x", "nan", "inf", "0x10", "1e999"). */
int c2g_split(char *line, char *fields[], int max);
int c2g_parse_real(const char *field, c2g_real *out);

#ifdef __cplusplus
}

/* C++: a matrix kept column by column and indexed m[column][row], as glm::mat4 and glm::dmat4
 * are, written whatever its number type: c2g_write_glm(f, 'M', M). which 'M', 'P' or 'V';
 * c2g_write_glm_model writes the model matrix. */
template <class Matrix> void c2g__glm_rows(const Matrix &m, c2g_real rows[16])
{
    for (int i = 0; i < 16; i++) rows[i] = (c2g_real)m[i % 4][i / 4];
}
template <class Matrix> void c2g_write_glm(FILE *f, char which, const Matrix &m)
{
    c2g_real rows[16];
    c2g__glm_rows(m, rows);
    c2g_write_matrix(f, which, rows);
}
template <class Matrix> void c2g_write_glm_model(FILE *f, const Matrix &m)
{
    c2g_real rows[16];
    c2g__glm_rows(m, rows);
    c2g_write_model_matrix(f, rows);
}
#endif
#endif /* CLOSE2GL_TRACE_H */

/* ------------------------------------------------------------------------------------------- */
#ifdef CLOSE2GL_TRACE_IMPLEMENTATION
#ifndef CLOSE2GL_TRACE_IMPLEMENTED
#define CLOSE2GL_TRACE_IMPLEMENTED

#include <ctype.h>
#include <errno.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

int c2g_split(char *line, char *fields[], int max)
{
    int count = 0;
    char *p = line;
    for (;;) {
        while (*p == ' ' || *p == '\t') *p++ = '\0';
        if (*p == '\0') return count;
        if (count == max) return max + 1;
        fields[count++] = p;
        while (*p && *p != ' ' && *p != '\t') p++;
    }
}

/* Is p a number as printf writes one: a sign, digits with an optional fraction, an exponent?
 * (strtod alone would also take "nan", "inf", "0x1p3" and " 1".) */
static int c2g__decimal(const char *p)
{
    int digits = 0;
    if (*p == '+' || *p == '-') p++;
    while (isdigit((unsigned char)*p)) p++, digits++;
    if (*p == '.')
        for (p++; isdigit((unsigned char)*p); p++) digits++;
    if (digits == 0) return 0;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!isdigit((unsigned char)*p)) return 0;
        while (isdigit((unsigned char)*p)) p++;
    }
    return *p == '\0';
}

int c2g_parse_real(const char *field, c2g_real *out)
{
#ifdef CLOSE2GL_FLOAT
    const double largest = FLT_MAX;
#else
    const double largest = DBL_MAX;
#endif
    double value;
    if (!c2g__decimal(field)) return 0;
    value = strtod(field, NULL);
    if (!(value >= -largest && value <= largest)) return 0; /* 1e999 would be inf */
    *out = (c2g_real)value;
    return 1;
}

/* ---- reading a scene ---- */

/* The keys that may be given once: the camera's first, in the order of camera_keys below. */
enum { C2G__POSITION, C2G__U, C2G__V, C2G__N, C2G__HFOV, C2G__VFOV, C2G__NEAR, C2G__FAR,
       C2G__FRAMED, C2G__MODEL, C2G__WINDOW, C2G__CULLING, C2G__CLIPPING, C2G__MODE, C2G__LOOKAT,
       C2G__SHADING, C2G__FILTER, C2G__COLOR, C2G__BACKGROUND, C2G__LIGHT, C2G__TEXTURE,
       C2G__KEYS };

/* One line of a scene, as the checks and their messages need it. */
typedef struct {
    const char *path;
    int number;        /* 1-based */
    const char *text;  /* the line without its comment and the blanks around it */
    char *field[8];
    int count;         /* 9: more than 8 fields */
} c2g__line;

/* Prints text as messages quote it: 60 characters at most, control characters as '?'. */
static void c2g__show(const char *text)
{
    int chars = 0;
    for (; *text; text++) {
        unsigned char c = (unsigned char)*text;
        if ((c & 0xC0) != 0x80 && chars++ == 60) break;  /* a UTF-8 character starts here */
        fputc(c < 0x20 || c == 0x7F ? '?' : c, stderr);
    }
    if (*text) fputs("\xE2\x80\xA6", stderr);            /* an ellipsis: there is more */
}

/* "file:line: expected WHAT, found 'FOUND'" on stderr; returns 0. */
static int c2g__expected(const c2g__line *l, const char *what, const char *found)
{
    fprintf(stderr, "%s:%d: expected %s, found '", l->path, l->number, what);
    c2g__show(found);
    fputs("'\n", stderr);
    return 0;
}

/* The line is not the shape its key needs: "expected 'SHAPE', found 'the line'". */
static int c2g__wrong(const c2g__line *l, const char *shape)
{
    char what[128];
    sprintf(what, "'%.120s'", shape);
    return c2g__expected(l, what, l->text);
}

static int c2g__fields(const c2g__line *l, int count, const char *shape)
{
    return l->count == count || c2g__wrong(l, shape);
}

/* Field i as a number; name is what shape calls it. */
static int c2g__number(const c2g__line *l, int i, const char *name, const char *shape,
                       c2g_real *out)
{
    char what[160];
    if (c2g_parse_real(l->field[i], out)) return 1;
    sprintf(what, "%s for %s in '%.100s'",
            c2g__decimal(l->field[i]) ? "a finite number" : "a number", name, shape);
    return c2g__expected(l, what, l->field[i]);
}

/* Fields first .. first + 2: X Y Z. */
static int c2g__xyz(const c2g__line *l, int first, const char *shape, c2g_real out[3])
{
    return c2g__number(l, first, "X", shape, &out[0])
           && c2g__number(l, first + 1, "Y", shape, &out[1])
           && c2g__number(l, first + 2, "Z", shape, &out[2]);
}

/* Fields 1 .. 3 of `color R G B` or `background R G B`: each a number in [0, 1]. */
static int c2g__rgb(const c2g__line *l, const char *shape, c2g_real out[3])
{
    char what[96];
    int k;
    for (k = 0; k < 3; k++) {
        char name[2] = {"RGB"[k], '\0'};
        if (!c2g__number(l, 1 + k, name, shape, &out[k])) return 0;
    }
    for (k = 0; k < 3; k++)
        if (!(out[k] >= 0 && out[k] <= 1)) {
            sprintf(what, "'%s' with R, G and B in [0, 1]", shape);
            return c2g__expected(l, what, l->text);
        }
    return 1;
}

/* A PATH field resolved against the scene file's folder (a relative one is relative to it). */
static int c2g__path(const c2g__line *l, const char *field, char out[1024])
{
    const char *slash = strrchr(l->path, '/');
    size_t i;
    if (strrchr(l->path, '\\') > slash) slash = strrchr(l->path, '\\');
    i = (slash && field[0] != '/' && field[0] != '\\' && field[1] != ':')
            ? (size_t)(slash - l->path + 1) : 0;
    if (i + strlen(field) >= 1024) {
        char what[64];
        sprintf(what, "a %s path of at most 1000 characters", l->field[0]);
        return c2g__expected(l, what, l->text);
    }
    memcpy(out, l->path, i);
    strcpy(out + i, field);
    return 1;
}

/* Field i of `window W H`: a whole number of pixels, 1 to 16384. */
static int c2g__pixels(const c2g__line *l, int i, const char *name, int *out)
{
    const char *p = l->field[i] + (l->field[i][0] == '+');
    char what[64];
    long value = 0;
    if (*p == '\0' || strspn(p, "0123456789") != strlen(p)) {
        sprintf(what, "a non-negative integer for %s in 'window W H'", name);
        return c2g__expected(l, what, l->field[i]);
    }
    for (; *p && value <= 16384; p++) value = 10 * value + (*p - '0');
    if (value < 1 || value > 16384)
        return c2g__expected(l, "'window W H' with W and H in 1..=16384", l->text);
    *out = (int)value;
    return 1;
}

/* A key given twice is an error at the second line. */
static int c2g__once(const c2g__line *l, int *seen, const char *key)
{
    char what[80];
    if (*seen) {
        sprintf(what, "one '%s' line (the first is line %d)", key, *seen);
        return c2g__expected(l, what, l->text);
    }
    *seen = l->number;
    return 1;
}

/* x with the fewest digits that read back the same, "2.0" rather than "2" (as close2gl says it). */
static void c2g__shortest(char out[32], double x)
{
    int digits;
    for (digits = 1; digits < 17; digits++) {
        snprintf(out, 32, "%.*g", digits, x);
        if (strtod(out, NULL) == x) break;
    }
    if (!strpbrk(out, ".e")) strcat(out, ".0");
}

/* The whole file, '\0'-terminated; NULL (errno set) when it cannot be read. */
static char *c2g__slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL, *grown = NULL;
    size_t capacity = 0, got;
    *size = 0;
    if (!f) return NULL;
    do {
        if (capacity - *size < 4096) {
            capacity = capacity ? 2 * capacity : 65536;
            grown = (char *)realloc(text, capacity + 1);
            if (!grown) break;
            text = grown;
        }
        got = fread(text + *size, 1, capacity - *size, f);
        *size += got;
    } while (got > 0);
    if (ferror(f) || !grown) {
        free(text);
        text = NULL;
    }
    fclose(f);
    if (text) text[*size] = '\0';
    return text;
}

int c2g_read_scene(const char *path, c2g_scene *s)
{
    static const char *const camera_keys[9] = {"position", "u", "v", "n", "hfov", "vfov",
                                               "near", "far", "framed"};
    static const char *const choice_keys[3] = {"culling", "clipping", "mode"};
    static const char *const choice_shapes[3] = {"culling off|ccw|cw", "clipping simple|full|none",
                                                 "mode points|wireframe|solid"};
    static const char *const choices[3][3] = {{"off", "ccw", "cw"}, {"simple", "full", "none"},
                                              {"points", "wireframe", "solid"}};
    static const char *const raster_shapes[2] = {"shading none|gouraud_ad|gouraud_ads|phong",
                                                 "filter nearest|bilinear|trilinear"};
    int seen[C2G__KEYS] = {0};
    int end_line = 0, magic = 0, last = 1, ok = 0, pose, i, k;
    char what[160], shape[40], number[32], *p, *next, *copy, *end;
    size_t size;
    c2g__line l;
    c2g_real x[3];
    char *text = c2g__slurp(path, &size);

    memset(s, 0, sizeof *s);
    s->hfov = s->vfov = 60;
    s->mode = C2G_MODE_SOLID;
    s->color[0] = s->color[1] = s->color[2] = 1;
    s->light[0] = 10, s->light[1] = 10, s->light[2] = 3;
    l.path = path;
    copy = text ? (char *)malloc(size + 1) : NULL;
    if (!copy) {
        fprintf(stderr, "%s:0: cannot read: %s\n", path, text ? "out of memory" : strerror(errno));
        free(text);
        return 0;
    }
/* FAIL(what): this line is not what was expected; TRY(check): a check that says why it fails. */
#define C2G__FAIL(what) do { c2g__expected(&l, what, l.text); goto done; } while (0)
#define C2G__TRY(check) do { if (!(check)) goto done; } while (0)
    p = text + (strncmp(text, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0);  /* a byte-order mark */
    for (l.number = 1; p; l.number++, p = next) {
        const char *key;
        if ((next = strchr(p, '\n')) != NULL) *next++ = '\0';
        if (next || *p) last = l.number;          /* a final '\n' does not start another line */
        if (p + strlen(p) < text + size && !next) {  /* stopped at a '\0' byte */
            fprintf(stderr, "%s:%d: expected text, found the byte 0x00\n", path, l.number);
            goto done;
        }
        end = p + strlen(p);
        if (end > p && end[-1] == '\r') *--end = '\0';         /* \r\n line ends */
        if ((end = strchr(p, '#')) != NULL) *end = '\0';       /* a comment runs to the end */
        p += strspn(p, " \t");
        for (end = p + strlen(p); end > p && (end[-1] == ' ' || end[-1] == '\t'); ) *--end = '\0';
        l.text = p;
        strcpy(copy, p);
        l.count = c2g_split(copy, l.field, 8);
        if (l.count == 0) continue;                            /* blank, or a comment */
        key = l.field[0];

        if (!magic) {                                          /* the first line: the version */
            if (l.count == 2 && !strcmp(key, "close2gl-scene") && !strcmp(l.field[1], "1")) {
                magic = 1;
                continue;
            }
            fprintf(stderr, "%s:%d: expected 'close2gl-scene 1', found '", path, l.number);
            c2g__show(l.text);
            if (l.count == 2 && !strcmp(key, "close2gl-scene"))
                fputs("' (this close2gl reads version 1)\n", stderr);
            else if (!strcmp(key, "close2gl-trace"))
                fputs("' (a trace file, not a scene)\n", stderr);
            else
                fputs("'\n", stderr);
            goto done;
        }
        if (end_line) {
            sprintf(what, "nothing after 'end' (line %d)", end_line);
            C2G__FAIL(what);
        }
        if (!strcmp(key, "camera")) {
            const char *which = l.count > 1 ? l.field[1] : "";
            for (i = 0; i < 9 && strcmp(which, camera_keys[i]) != 0; i++) {}
            if (i == C2G__FRAMED) {
                C2G__TRY(c2g__fields(&l, 2, "camera framed"));
                for (pose = 0, k = C2G__POSITION; k <= C2G__N; k++)
                    if (seen[k] && (!pose || seen[k] < pose)) pose = seen[k];
                if (pose) {
                    sprintf(what, "'camera framed' or a pose (line %d), not both", pose);
                    C2G__FAIL(what);
                }
                C2G__TRY(c2g__once(&l, &seen[C2G__FRAMED], "camera framed"));
                s->framed = 1;
            } else if (i <= C2G__N && seen[C2G__FRAMED]) {
                sprintf(what, "only 'camera hfov|vfov|near|far' after 'camera framed' (line %d)",
                        seen[C2G__FRAMED]);
                C2G__FAIL(what);
            } else if (i == 9) {
                C2G__FAIL("'camera position|u|v|n X Y Z' or 'camera hfov|vfov|near|far D'");
            } else if (i <= C2G__N) {                          /* position, u, v, n */
                sprintf(shape, "camera %s X Y Z", which);
                C2G__TRY(c2g__fields(&l, 5, shape) && c2g__xyz(&l, 2, shape, x));
                sprintf(shape, "camera %s", which);
                C2G__TRY(c2g__once(&l, &seen[i], shape));
                memcpy(i == C2G__POSITION ? s->position
                       : i == C2G__U ? s->u : i == C2G__V ? s->v : s->n, x, sizeof x);
            } else {                                           /* hfov, vfov, near, far */
                const char *name = i <= C2G__VFOV ? "DEG" : "D";
                sprintf(shape, "camera %s %s", which, name);
                C2G__TRY(c2g__fields(&l, 3, shape) && c2g__number(&l, 2, name, shape, x));
                what[0] = '\0';
                if (i <= C2G__VFOV && !(x[0] > 0 && x[0] < 180))
                    sprintf(what, "'%s' with DEG in (0, 180)", shape);
                else if (i >= C2G__NEAR && !(x[0] > 0))
                    sprintf(what, "'%s' with D > 0", shape);
                else if (i == C2G__NEAR && seen[C2G__FAR] && !(x[0] < s->zfar))
                    c2g__shortest(number, (double)s->zfar),
                    sprintf(what, "'%s' with D < far (%s, line %d)", shape, number,
                            seen[C2G__FAR]);
                else if (i == C2G__FAR && seen[C2G__NEAR] && !(x[0] > s->znear))
                    c2g__shortest(number, (double)s->znear),
                    sprintf(what, "'%s' with D > near (%s, line %d)", shape, number,
                            seen[C2G__NEAR]);
                if (what[0]) C2G__FAIL(what);
                sprintf(shape, "camera %s", which);
                C2G__TRY(c2g__once(&l, &seen[i], shape));
                if (i == C2G__HFOV) s->hfov = x[0];
                if (i == C2G__VFOV) s->vfov = x[0];
                if (i == C2G__NEAR) s->znear = x[0], s->has_near = 1;
                if (i == C2G__FAR) s->zfar = x[0], s->has_far = 1;
            }
        } else if (!strcmp(key, "model")) {
            /* A relative PATH is relative to the scene file's folder. */
            C2G__TRY(c2g__fields(&l, 2, "model PATH"));
            C2G__TRY(c2g__once(&l, &seen[C2G__MODEL], "model"));
            C2G__TRY(c2g__path(&l, l.field[1], s->model));
        } else if (!strcmp(key, "texture")) {
            C2G__TRY(c2g__fields(&l, 2, "texture PATH"));
            C2G__TRY(c2g__once(&l, &seen[C2G__TEXTURE], "texture"));
            C2G__TRY(c2g__path(&l, l.field[1], s->texture));
            s->has_texture = 1;
        } else if (!strcmp(key, "shading") || !strcmp(key, "filter")) {
            static const char *const options[2][5] = {
                {"none", "gouraud_ad", "gouraud_ads", "phong", NULL},
                {"nearest", "bilinear", "trilinear", NULL, NULL}};
            i = key[0] == 'f';
            C2G__TRY(c2g__fields(&l, 2, raster_shapes[i]));
            for (k = 0; options[i][k] && strcmp(l.field[1], options[i][k]) != 0; k++) {}
            C2G__TRY(options[i][k] || c2g__wrong(&l, raster_shapes[i]));
            C2G__TRY(c2g__once(&l, &seen[C2G__SHADING + i], key));
            *(i == 0 ? &s->shading : &s->filter) = k;
        } else if (!strcmp(key, "color") || !strcmp(key, "background")) {
            i = key[0] == 'b';
            sprintf(shape, "%s R G B", key);
            C2G__TRY(c2g__fields(&l, 4, shape) && c2g__rgb(&l, shape, i ? s->background : s->color));
            C2G__TRY(c2g__once(&l, &seen[C2G__COLOR + i], key));
        } else if (!strcmp(key, "light")) {
            C2G__TRY(c2g__fields(&l, 4, "light X Y Z") && c2g__xyz(&l, 1, "light X Y Z", s->light));
            C2G__TRY(c2g__once(&l, &seen[C2G__LIGHT], "light"));
        } else if (!strcmp(key, "window")) {
            C2G__TRY(c2g__fields(&l, 3, "window W H") && c2g__pixels(&l, 1, "W", &s->width)
                     && c2g__pixels(&l, 2, "H", &s->height));
            C2G__TRY(c2g__once(&l, &seen[C2G__WINDOW], "window"));
        } else if (!strcmp(key, "culling") || !strcmp(key, "clipping") || !strcmp(key, "mode")) {
            i = key[0] == 'c' ? key[1] == 'u' ? 0 : 1 : 2;
            C2G__TRY(c2g__fields(&l, 2, choice_shapes[i]));
            for (k = 0; k < 3 && strcmp(l.field[1], choices[i][k]) != 0; k++) {}
            C2G__TRY(k < 3 || c2g__wrong(&l, choice_shapes[i]));
            C2G__TRY(c2g__once(&l, &seen[C2G__CULLING + i], choice_keys[i]));
            *(i == 0 ? &s->culling : i == 1 ? &s->clipping : &s->mode) = k;
        } else if (!strcmp(key, "lookat")) {
            C2G__TRY(c2g__fields(&l, 4, "lookat X Y Z")
                     && c2g__xyz(&l, 1, "lookat X Y Z", s->lookat));
            C2G__TRY(c2g__once(&l, &seen[C2G__LOOKAT], "lookat"));
            s->has_lookat = 1;
        } else if (!strcmp(key, "move") || !strcmp(key, "rotate") || !strcmp(key, "orbit")) {
            c2g_motion m, *grown;
            const char *form = key[0] == 'm' ? "move u|v|n D" : key[0] == 'r' ? "rotate u|v|n DEG"
                                                                               : "orbit u|v D";
            m.kind = key[0];
            C2G__TRY(c2g__fields(&l, 3, form));
            m.axis = l.field[1][0];
            C2G__TRY((l.field[1][1] == '\0' && strchr(m.kind == 'o' ? "uv" : "uvn", m.axis))
                     || c2g__wrong(&l, form));
            C2G__TRY(c2g__number(&l, 2, m.kind == 'r' ? "DEG" : "D", form, &m.amount));
            grown = (c2g_motion *)realloc(s->motions, (size_t)(s->motion_count + 1) * sizeof m);
            if (!grown) C2G__FAIL("memory for one more motion");
            s->motions = grown;
            s->motions[s->motion_count++] = m;
        } else if (!strcmp(key, "end")) {
            C2G__TRY(c2g__fields(&l, 1, "end"));
            end_line = l.number;
        } else {
            C2G__FAIL("a scene line (model, window, camera, culling, clipping, mode, lookat, move, "
                      "rotate, orbit, shading, color, background, light, texture, filter or end)");
        }
    }
#undef C2G__FAIL
#undef C2G__TRY

    /* The whole file is read: what is missing is reported at its last line. */
    what[0] = '\0';
    if (!magic) {
        fprintf(stderr, "%s:%d: expected 'close2gl-scene 1', found end of file\n", path, last);
        goto done;
    }
    if (!seen[C2G__MODEL]) strcpy(what, "'model PATH'");
    else if (!seen[C2G__WINDOW]) strcpy(what, "'window W H'");
    else if (!s->framed) {
        static const char *const lines[8] = {
            "'camera position X Y Z'", "'camera u X Y Z'", "'camera v X Y Z'", "'camera n X Y Z'",
            "'camera hfov DEG'", "'camera vfov DEG'", "'camera near D'", "'camera far D'"};
        for (i = 0; i < 8 && seen[i]; i++) {}
        if (!seen[C2G__POSITION] && !seen[C2G__U] && !seen[C2G__V] && !seen[C2G__N])
            strcpy(what, "'camera framed' or 'camera position X Y Z'");
        else if (i < 8)
            strcpy(what, lines[i]);
    }
    if (what[0]) {
        fprintf(stderr, "%s:%d: the scene ends without %s\n", path, last, what);
        goto done;
    }
    ok = 1;
done:
    free(text);
    free(copy);
    if (!ok) c2g_free_scene(s);
    return ok;
}

void c2g_free_scene(c2g_scene *scene)
{
    free(scene->motions);
    scene->motions = NULL;
    scene->motion_count = 0;
}

/* ---- writing ---- */

/* The trace the last c2g_write_header started: its FILE, how many tri and poly lines it has, and
 * whether it gave any 2D output at all (a clip, tri or poly line). One trace at a time keeps
 * every write's signature a plain FILE *; a struct handle would change every call of every
 * program already instrumented. */
static FILE *c2g__trace;
static long c2g__pieces;
static int c2g__output;

static void c2g__piece(FILE *f, int piece)
{
    if (f != c2g__trace) return;
    c2g__output = 1;
    c2g__pieces += piece;
}

static void c2g__numbers(FILE *f, const c2g_real *x, int count)
{
    int i;
    for (i = 0; i < count; i++) fprintf(f, C2G_FMT, x[i]);
    fputc('\n', f);
}

void c2g_write_header(FILE *f)
{
    c2g__trace = f;
    c2g__pieces = 0;
    c2g__output = 0;
    fputs("close2gl-trace 1\n", f);
}

void c2g_write_model(FILE *f, const char *name)
{
    /* A name is one field: spaces and '#' would break the line, so they become '_'. */
    fputs("model ", f);
    for (; *name; name++) fputc(strchr(" \t\r\n#", *name) ? '_' : *name, f);
    fputc('\n', f);
}

void c2g_write_triangles(FILE *f, int count) { fprintf(f, "triangles %d\n", count); }

void c2g_write_window(FILE *f, int width, int height)
{
    fprintf(f, "window %d %d\n", width, height);
}

void c2g_write_ortho2d(FILE *f, c2g_real left, c2g_real right, c2g_real bottom, c2g_real top)
{
    c2g_real x[4];
    x[0] = left, x[1] = right, x[2] = bottom, x[3] = top;
    fputs("ortho2d", f);
    c2g__numbers(f, x, 4);
}

void c2g_write_ortho2d_ndc(FILE *f) { c2g_write_ortho2d(f, -1, 1, -1, 1); }

void c2g_write_camera(FILE *f, const c2g_real position[3], const c2g_real u[3],
                      const c2g_real v[3], const c2g_real n[3], c2g_real hfov, c2g_real vfov,
                      c2g_real znear, c2g_real zfar)
{
    fputs("camera position", f); c2g__numbers(f, position, 3);
    fputs("camera u", f);        c2g__numbers(f, u, 3);
    fputs("camera v", f);        c2g__numbers(f, v, 3);
    fputs("camera n", f);        c2g__numbers(f, n, 3);
    fputs("camera hfov", f);     c2g__numbers(f, &hfov, 1);
    fputs("camera vfov", f);     c2g__numbers(f, &vfov, 1);
    fputs("camera near", f);     c2g__numbers(f, &znear, 1);
    fputs("camera far", f);      c2g__numbers(f, &zfar, 1);
}

void c2g_write_culling_in(FILE *f, int culling, int space)
{
    const char *in = space == C2G_CULL_IN_NDC ? " ndc" : space == C2G_CULL_IN_WINDOW ? " window" : "";
    if (culling != C2G_CULL_CCW && culling != C2G_CULL_CW) in = ""; /* off has no space */
    fprintf(f, "culling %s%s\n",
            culling == C2G_CULL_CCW ? "ccw" : culling == C2G_CULL_CW ? "cw" : "off", in);
}

void c2g_write_culling(FILE *f, int culling) { c2g_write_culling_in(f, culling, C2G_CULL_ON_SCREEN); }

void c2g_write_clipping(FILE *f, int clipping)
{
    fprintf(f, "clipping %s\n", clipping == C2G_CLIP_FULL ? "full"
                                : clipping == C2G_CLIP_NONE ? "none"
                                : clipping == C2G_CLIP_SIMPLE_NEAR_FAR ? "simple near_far"
                                : clipping == C2G_CLIP_FULL_NEAR_FAR ? "full near_far" : "simple");
}

void c2g_write_mode(FILE *f, int mode)
{
    fprintf(f, "mode %s\n", mode == C2G_MODE_POINTS ? "points"
                            : mode == C2G_MODE_WIREFRAME ? "wireframe" : "solid");
}

static void c2g__matrix(FILE *f, const char *name, const c2g_real *m, int columns)
{
    c2g_real rows[16];
    int i;
    for (i = 0; i < 16; i++) rows[i] = columns ? m[4 * (i % 4) + i / 4] : m[i];
    fprintf(f, "matrix %s", name);
    c2g__numbers(f, rows, 16);
}

void c2g_write_matrix(FILE *f, char which, const c2g_real *m)
{
    char name[2];
    name[0] = which, name[1] = '\0';
    c2g__matrix(f, name, m, 0);
}

void c2g_write_matrix_columns(FILE *f, char which, const c2g_real *m)
{
    char name[2];
    name[0] = which, name[1] = '\0';
    c2g__matrix(f, name, m, 1);
}

void c2g_write_model_matrix(FILE *f, const c2g_real *m) { c2g__matrix(f, "model", m, 0); }

void c2g_write_model_matrix_columns(FILE *f, const c2g_real *m)
{
    c2g__matrix(f, "model", m, 1);
}

void c2g_write_clip(FILE *f, int t, const c2g_real *clip)
{
    c2g__piece(f, 0);
    fprintf(f, "clip %d", t);
    c2g__numbers(f, clip, 12);
}

void c2g_write_tri(FILE *f, int t, const c2g_real *corners, int dims)
{
    c2g__piece(f, 1);
    fprintf(f, "tri %d", t);
    c2g__numbers(f, corners, 3 * dims);
}

void c2g_write_poly(FILE *f, int t, int k, const c2g_real *corners, int dims)
{
    c2g__piece(f, 1);
    fprintf(f, "poly %d %d", t, k);
    c2g__numbers(f, corners, k * dims);
}

void c2g_write_triangle(FILE *f, int t, const c2g_real *clip, const c2g_real *corners, int k,
                        int dims)
{
    c2g__piece(f, 0);    /* the program handled this triangle: its 2D output is given */
    if (clip) c2g_write_clip(f, t, clip);
    if (!corners || k < 3) return;
    if (k == 3) c2g_write_tri(f, t, corners, dims);
    else c2g_write_poly(f, t, k, corners, dims);
}

void c2g_write_end(FILE *f)
{
    if (f == c2g__trace && c2g__output) fprintf(f, "drawn %ld\n", c2g__pieces);
    if (f == c2g__trace) c2g__trace = NULL;
    fputs("end\n", f);
}

#ifdef __cplusplus
}
#endif
#endif /* CLOSE2GL_TRACE_IMPLEMENTED */
#endif /* CLOSE2GL_TRACE_IMPLEMENTATION */
