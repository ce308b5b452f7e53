/* close2gl_raster.h: write a close2gl raster trace (format version 1) and the two buffers it
 * points to, and read a PPM texture. See docs/raster-trace-format.md.
 *
 * Header-only C99 (it compiles as C++ too). In exactly one .c or .cpp file write
 *
 *     #define CLOSE2GL_RASTER_IMPLEMENTATION
 *     #include "close2gl_raster.h"
 *
 * and include it plainly everywhere else. Numbers are c2r_real: double, or float when compiled
 * with -DCLOSE2GL_FLOAT (use that if your program computes in float); they are printed with
 * %.17g (double) or %.9g (float), enough digits to read back the very same value.
 *
 * A trace: c2r_write_header, the settings lines, c2r_write_attributes, one c2r_write_tri per
 * triangle rasterized (in the order it was rasterized), c2r_write_end (`drawn N` and `end`).
 * The buffers: c2r_write_ppm (the RGB8 colour buffer) and c2r_write_pfm (the float depth buffer),
 * each told whether the program's array holds its top row first or its bottom row first; they
 * turn it into what the file format says (PPM top row first, PFM bottom row first).
 *
 *     FILE *f = fopen("frame.raster", "w");
 *     c2r_write_header(f);
 *     c2r_write_window(f, W, H);
 *     c2r_write_framebuffer(f, "frame.raster.ppm");   // relative to the trace's folder
 *     c2r_write_depthbuffer(f, "frame.raster.pfm");
 *     c2r_write_attributes(f, C2R_RGB);                // window x y z q, then r g b
 *     ... for each triangle rasterized: c2r_write_tri(f, t, corners);  // 3 x (4 + 3) numbers
 *     c2r_write_end(f);
 *     fclose(f);
 *     c2r_write_ppm("frame.raster.ppm", rgb, W, H, C2R_TOP_ROW_FIRST);
 *     c2r_write_pfm("frame.raster.pfm", depth, W, H, C2R_TOP_ROW_FIRST);
 *
 * Both use the C library's number formats, which follow the locale: keep LC_NUMERIC at "C".
 */
#ifndef CLOSE2GL_RASTER_H
#define CLOSE2GL_RASTER_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#ifdef CLOSE2GL_FLOAT
typedef float c2r_real;
#define C2R_FMT " %.9g"
#else
typedef double c2r_real;
#define C2R_FMT " %.17g"
#endif

enum { C2R_ORIGIN_BOTTOM_LEFT, C2R_ORIGIN_TOP_LEFT };
enum { C2R_SHADING_NONE, C2R_SHADING_GOURAUD_AD, C2R_SHADING_GOURAUD_ADS, C2R_SHADING_PHONG };
enum { C2R_FILTER_NEAREST, C2R_FILTER_BILINEAR, C2R_FILTER_TRILINEAR };
/* The attributes a corner carries after its window x y z q: any of these, or'ed (the trace
 * gives them in this order whatever the order of the flags). */
enum { C2R_RGB = 1, C2R_EYE = 2, C2R_NORMAL = 4, C2R_UV = 8 };
/* Which row of the program's own array comes first. */
enum { C2R_TOP_ROW_FIRST = 1, C2R_BOTTOM_ROW_FIRST = 0 };

/* Trace lines, in the order a trace usually has them. Colours and positions are 3 numbers. */
/* fopen(path, "w") and c2r_write_header: NULL after printing why on stderr. */
FILE *c2r_open(const char *path);
void c2r_write_header(FILE *f);                              /* close2gl-raster 1 */
void c2r_write_model(FILE *f, const char *name);
void c2r_write_window(FILE *f, int width, int height);
void c2r_write_origin(FILE *f, int origin);                  /* C2R_ORIGIN_... */
void c2r_write_subpixel(FILE *f, int bits);                  /* snapped to 1/2^bits pixel */
void c2r_write_shading(FILE *f, int shading);                /* C2R_SHADING_... */
void c2r_write_color(FILE *f, const c2r_real rgb[3]);
void c2r_write_background(FILE *f, const c2r_real rgb[3]);
void c2r_write_light(FILE *f, const c2r_real position[3]);  /* in world coordinates */
/* The modelview matrix M, row by row (m[4*row + column]); _columns for a column-major array
 * (OpenGL's and glm's order, m[4*column + row]). */
void c2r_write_matrix(FILE *f, const c2r_real *m);
void c2r_write_matrix_columns(FILE *f, const c2r_real *m);
/* Ia, Il, ka, kd, ks, the shininess n and the attenuation c0 c1 c2. */
void c2r_write_lighting(FILE *f, const c2r_real ia[3], const c2r_real il[3], c2r_real ka,
                        c2r_real kd, c2r_real ks, c2r_real shininess,
                        const c2r_real attenuation[3]);
/* The texture sampled (a PPM, relative to the trace's folder) and its filter C2R_FILTER_... */
void c2r_write_texture(FILE *f, const char *path, int filter);
void c2r_write_framebuffer(FILE *f, const char *path);       /* relative to the trace's folder */
void c2r_write_depthbuffer(FILE *f, const char *path);
/* Both lines for the buffers c2r_write_buffers will write beside the trace trace_path:
 * `framebuffer NAME.ppm` and `depthbuffer NAME.pfm`, NAME the trace's file name. */
void c2r_write_buffer_names(FILE *f, const char *trace_path);
/* `attributes window ...`: C2R_RGB | C2R_EYE | C2R_NORMAL | C2R_UV, or 0 for the window alone.
 * It sets how many numbers each corner of the next c2r_write_tri has: 4 (x y z q), + 3 rgb,
 * + 3 eye, + 3 normal, + 2 uv. */
void c2r_write_attributes(FILE *f, int attributes);
/* A triangle rasterized for mesh triangle t (0-based, the model file's order): its 3 corners one
 * after the other, each x y z q (window x, y; depth in [0, 1]; q = 1/w) then the attributes. */
void c2r_write_tri(FILE *f, int t, const c2r_real *corners);
/* The same with the number of values per corner given (not the last attributes line's). */
void c2r_write_tri_n(FILE *f, int t, const c2r_real *corners, int per_corner);
/* `drawn N` (the tri lines of the trace the last c2r_write_header started), then `end`. */
void c2r_write_end(FILE *f);
/* c2r_write_end and fclose: 1, or 0 after printing why on stderr. */
int c2r_close(FILE *f);

/* The buffers. rgb: width*height*3 bytes, row after row; depth: width*height floats. row_order
 * C2R_TOP_ROW_FIRST or C2R_BOTTOM_ROW_FIRST says how the program's array is laid out. 1 when
 * written, 0 after printing why on stderr. */
int c2r_write_ppm(const char *path, const unsigned char *rgb, int width, int height,
                  int row_order);
int c2r_write_pfm(const char *path, const float *depth, int width, int height, int row_order);
/* Both, beside the trace trace_path: TRACE.ppm and TRACE.pfm (the names that
 * c2r_write_buffer_names gives); depth NULL: the PPM alone. */
int c2r_write_buffers(const char *trace_path, const unsigned char *rgb, const float *depth,
                      int width, int height, int row_order);
/* Reads a PPM (P6 or P3, maxval 1..65535, scaled to 0..255): width*height*3 bytes, malloc'ed,
 * top row first (as the file has them); NULL after printing why on stderr. free() it. */
unsigned char *c2r_read_ppm(const char *path, int *width, int *height);

#ifdef __cplusplus
}
#endif
#endif /* CLOSE2GL_RASTER_H */

/* ------------------------------------------------------------------------------------------- */
#ifdef CLOSE2GL_RASTER_IMPLEMENTATION
#ifndef CLOSE2GL_RASTER_IMPLEMENTED
#define CLOSE2GL_RASTER_IMPLEMENTED

#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The trace the last c2r_write_header started: its FILE, its tri lines, the numbers per corner. */
static FILE *c2r__trace;
static long c2r__tris;
static int c2r__per_corner = 4;

static void c2r__numbers(FILE *f, const c2r_real *x, int count)
{
    int i;
    for (i = 0; i < count; i++) fprintf(f, C2R_FMT, x[i]);
    fputc('\n', f);
}

/* A name or path is one field: blanks and '#' would break the line, so they become '_'. */
static void c2r__field_ending(FILE *f, const char *key, const char *text, const char *ending)
{
    fprintf(f, "%s ", key);
    for (; *text; text++) fputc(strchr(" \t\r\n#", *text) ? '_' : *text, f);
    fprintf(f, "%s\n", ending);
}

static void c2r__field(FILE *f, const char *key, const char *text)
{
    c2r__field_ending(f, key, text, "");
}

FILE *c2r_open(const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f) fprintf(stderr, "%s: %s\n", path, strerror(errno));
    else c2r_write_header(f);
    return f;
}

void c2r_write_header(FILE *f)
{
    c2r__trace = f;
    c2r__tris = 0;
    c2r__per_corner = 4;
    fputs("close2gl-raster 1\n", f);
}

void c2r_write_model(FILE *f, const char *name) { c2r__field(f, "model", name); }

void c2r_write_window(FILE *f, int width, int height)
{
    fprintf(f, "window %d %d\n", width, height);
}

void c2r_write_origin(FILE *f, int origin)
{
    fprintf(f, "origin %s\n", origin == C2R_ORIGIN_TOP_LEFT ? "top-left" : "bottom-left");
}

void c2r_write_subpixel(FILE *f, int bits) { fprintf(f, "subpixel %d\n", bits); }

void c2r_write_shading(FILE *f, int shading)
{
    static const char *const names[4] = {"none", "gouraud_ad", "gouraud_ads", "phong"};
    fprintf(f, "shading %s\n", names[shading >= 0 && shading < 4 ? shading : 0]);
}

void c2r_write_color(FILE *f, const c2r_real rgb[3])
{
    fputs("color", f);
    c2r__numbers(f, rgb, 3);
}

void c2r_write_background(FILE *f, const c2r_real rgb[3])
{
    fputs("background", f);
    c2r__numbers(f, rgb, 3);
}

void c2r_write_light(FILE *f, const c2r_real position[3])
{
    fputs("light", f);
    c2r__numbers(f, position, 3);
}

void c2r_write_matrix(FILE *f, const c2r_real *m)
{
    fputs("matrix M", f);
    c2r__numbers(f, m, 16);
}

void c2r_write_matrix_columns(FILE *f, const c2r_real *m)
{
    c2r_real rows[16];
    int i;
    for (i = 0; i < 16; i++) rows[i] = m[4 * (i % 4) + i / 4];
    c2r_write_matrix(f, rows);
}

void c2r_write_lighting(FILE *f, const c2r_real ia[3], const c2r_real il[3], c2r_real ka,
                        c2r_real kd, c2r_real ks, c2r_real shininess,
                        const c2r_real attenuation[3])
{
    c2r_real x[13];
    int i;
    for (i = 0; i < 3; i++) x[i] = ia[i], x[3 + i] = il[i], x[10 + i] = attenuation[i];
    x[6] = ka, x[7] = kd, x[8] = ks, x[9] = shininess;
    fputs("lighting", f);
    c2r__numbers(f, x, 13);
}

void c2r_write_texture(FILE *f, const char *path, int filter)
{
    c2r__field(f, "texture", path);
    fprintf(f, "filter %s\n", filter == C2R_FILTER_TRILINEAR ? "trilinear"
                              : filter == C2R_FILTER_BILINEAR ? "bilinear" : "nearest");
}

void c2r_write_framebuffer(FILE *f, const char *path) { c2r__field(f, "framebuffer", path); }

void c2r_write_depthbuffer(FILE *f, const char *path) { c2r__field(f, "depthbuffer", path); }

/* The trace's file name: the buffers lie in its folder. */
static const char *c2r__base(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (strrchr(path, '\\') > slash) slash = strrchr(path, '\\');
    return slash ? slash + 1 : path;
}

void c2r_write_buffer_names(FILE *f, const char *trace_path)
{
    c2r__field_ending(f, "framebuffer", c2r__base(trace_path), ".ppm");
    c2r__field_ending(f, "depthbuffer", c2r__base(trace_path), ".pfm");
}

void c2r_write_attributes(FILE *f, int attributes)
{
    fputs("attributes window", f);
    if (attributes & C2R_RGB) fputs(" rgb", f);
    if (attributes & C2R_EYE) fputs(" eye", f);
    if (attributes & C2R_NORMAL) fputs(" normal", f);
    if (attributes & C2R_UV) fputs(" uv", f);
    fputc('\n', f);
    if (f == c2r__trace)
        c2r__per_corner = 4 + 3 * !!(attributes & C2R_RGB) + 3 * !!(attributes & C2R_EYE)
                          + 3 * !!(attributes & C2R_NORMAL) + 2 * !!(attributes & C2R_UV);
}

void c2r_write_tri_n(FILE *f, int t, const c2r_real *corners, int per_corner)
{
    if (f == c2r__trace) c2r__tris++;
    fprintf(f, "tri %d", t);
    c2r__numbers(f, corners, 3 * per_corner);
}

void c2r_write_tri(FILE *f, int t, const c2r_real *corners)
{
    c2r_write_tri_n(f, t, corners, f == c2r__trace ? c2r__per_corner : 4);
}

void c2r_write_end(FILE *f)
{
    if (f == c2r__trace) fprintf(f, "drawn %ld\n", c2r__tris);
    if (f == c2r__trace) c2r__trace = NULL;
    fputs("end\n", f);
}

int c2r_close(FILE *f)
{
    c2r_write_end(f);
    if (ferror(f) | fclose(f)) {
        fprintf(stderr, "the raster trace: %s\n", strerror(errno));
        return 0;
    }
    return 1;
}

/* ---- the buffers ---- */

static int c2r__failed(const char *path, FILE *f)
{
    fprintf(stderr, "%s: %s\n", path, strerror(errno));
    if (f) fclose(f);
    return 0;
}

int c2r_write_ppm(const char *path, const unsigned char *rgb, int width, int height,
                  int row_order)
{
    FILE *f = fopen(path, "wb");
    int y;
    if (!f) return c2r__failed(path, NULL);
    fprintf(f, "P6\n%d %d\n255\n", width, height);
    for (y = 0; y < height; y++) {            /* the file's rows from the top */
        int row = row_order == C2R_TOP_ROW_FIRST ? y : height - 1 - y;
        fwrite(rgb + (size_t)row * width * 3, 3, (size_t)width, f);
    }
    if (ferror(f)) return c2r__failed(path, f);
    return fclose(f) == 0 || c2r__failed(path, NULL);
}

int c2r_write_pfm(const char *path, const float *depth, int width, int height, int row_order)
{
    FILE *f = fopen(path, "wb");
    int x, y, k;
    if (!f) return c2r__failed(path, NULL);
    fprintf(f, "Pf\n%d %d\n-1.0\n", width, height);   /* a negative scale: little-endian */
    for (y = 0; y < height; y++) {            /* the file's rows from the bottom */
        int row = row_order == C2R_TOP_ROW_FIRST ? height - 1 - y : y;
        for (x = 0; x < width; x++) {
            float value = depth[(size_t)row * width + x];
            uint32_t bits;                    /* the float's bits, little-endian on any host */
            unsigned char bytes[4];
            memcpy(&bits, &value, 4);
            for (k = 0; k < 4; k++) bytes[k] = (unsigned char)(bits >> (8 * k));
            fwrite(bytes, 1, 4, f);
        }
    }
    if (ferror(f)) return c2r__failed(path, f);
    return fclose(f) == 0 || c2r__failed(path, NULL);
}

int c2r_write_buffers(const char *trace_path, const unsigned char *rgb, const float *depth,
                      int width, int height, int row_order)
{
    size_t length = strlen(trace_path);
    char *name = (char *)malloc(length + 5);
    int ok;
    if (!name) {
        fprintf(stderr, "%s: out of memory\n", trace_path);
        return 0;
    }
    memcpy(name, trace_path, length);
    strcpy(name + length, ".ppm");
    ok = c2r_write_ppm(name, rgb, width, height, row_order);
    strcpy(name + length, ".pfm");
    ok = ok && (!depth || c2r_write_pfm(name, depth, width, height, row_order));
    free(name);
    return ok;
}

/* The next header field of a PPM: a whole number after blanks and '#' comments; -1 if none. */
static long c2r__header_number(FILE *f)
{
    int c = fgetc(f);
    long value = 0, digits = 0;
    for (;;) {
        while (c != EOF && isspace(c)) c = fgetc(f);
        if (c != '#') break;
        while (c != EOF && c != '\n') c = fgetc(f);
    }
    for (; c != EOF && isdigit(c) && value < 100000; c = fgetc(f), digits++)
        value = 10 * value + (c - '0');
    if (!digits || (c != EOF && !isspace(c))) return -1;  /* one blank ends the header */
    return value;
}

unsigned char *c2r_read_ppm(const char *path, int *width, int *height)
{
    FILE *f = fopen(path, "rb");
    unsigned char *rgb = NULL;
    char magic[3] = {0, 0, 0};
    long w, h, maxval, value;
    size_t i, count;
    if (!f) {
        c2r__failed(path, NULL);
        return NULL;
    }
    if (fread(magic, 1, 2, f) != 2 || magic[0] != 'P' || (magic[1] != '6' && magic[1] != '3')) {
        fprintf(stderr, "%s: expected a PPM image (P6 or P3)\n", path);
        fclose(f);
        return NULL;
    }
    w = c2r__header_number(f);
    h = c2r__header_number(f);
    maxval = c2r__header_number(f);
    if (w < 1 || h < 1 || w > 65536 || h > 65536 || maxval < 1 || maxval > 65535) {
        fprintf(stderr, "%s: expected a PPM header 'P6|P3 W H MAXVAL' (W, H in 1..65536, "
                        "MAXVAL in 1..65535)\n", path);
        fclose(f);
        return NULL;
    }
    count = (size_t)w * (size_t)h * 3;
    rgb = (unsigned char *)malloc(count);
    for (i = 0; rgb && i < count; i++) {
        if (magic[1] == '3') {
            value = c2r__header_number(f);
        } else if (maxval < 256) {
            int c = fgetc(f);
            value = c == EOF ? -1 : c;
        } else {                               /* two bytes, most significant first */
            int hi = fgetc(f), lo = fgetc(f);
            value = hi == EOF || lo == EOF ? -1 : hi * 256 + lo;
        }
        if (value < 0 || value > maxval) {
            fprintf(stderr, "%s: expected %ld samples in 0..%ld, found %s at sample %lu\n", path,
                    (long)count, maxval, value < 0 ? "the end (or a bad number)" : "a larger one",
                    (unsigned long)i);
            free(rgb);
            fclose(f);
            return NULL;
        }
        rgb[i] = (unsigned char)(maxval == 255 ? value : (value * 255 + maxval / 2) / maxval);
    }
    fclose(f);
    if (!rgb) {
        fprintf(stderr, "%s: out of memory\n", path);
        return NULL;
    }
    *width = (int)w;
    *height = (int)h;
    return rgb;
}

#ifdef __cplusplus
}
#endif
#endif /* CLOSE2GL_RASTER_IMPLEMENTED */
#endif /* CLOSE2GL_RASTER_IMPLEMENTATION */
