// cpp_barycentric.cpp: a C++17 rasterizer in double, the way the "modern" lecture notes draw a
// triangle: its bounding box (clamped to the window), and for each pixel centre the barycentric
// weights as ratios of signed areas, inside when all three are >= 0 (a centre on an edge is in
// both triangles: the inclusive rule, which check cannot see without a `subpixel` line, since
// such centres are then no facts). No integer edge functions, no snapping. Window coordinates
// OpenGL's: y up, the buffers bottom row first. Clips against the near plane only (the box is
// clamped to the window: a guard band), culls by the winding on screen. Depth affine in the
// weights; every varying perspective-correct (sum w_i q_i a_i / sum w_i q_i). Textures: its own
// mip chain (levels of doubles, each texel the plain mean of four, not rounded to 8 bits),
// nearest, bilinear, trilinear with λ from the 2x2 quad whose top-left pixel starts at an even
// column and an even row counted from the top, as the assignment says.
//
//     cpp_barycentric SCENE TRACE      (TRACE.ppm, TRACE.pfm and TRACE.texture.ppm beside it)
//
// Variants, each a bug students make:
//   -DAFFINE_UV         s, t blended with the screen weights alone, λ too (uv_affine)
//   -DLOD_ACROSS_ONLY   ρ from the step across the quad only (lod_one_axis)
//   -DT_DOWN            t = 0 taken as the image's top row (t_not_flipped)
//   -DBIAS_BILINEAR     bilinear weights from s·W without the − 0.5 (bilinear_no_half_texel)
//
// Lines ending in "[trace]" were added only to write the trace.
//
// expect square: agree
// expect twice: agree
// expect cube_flat: agree
// expect cube_phong: agree
// expect knot_phong: agree
// expect cube_gouraud_ads: agree
// expect floor_nearest: agree
// expect floor_bilinear: agree
// expect floor_trilinear: agree
// expect cube_nearest: agree
// expect cube_trilinear: agree
// expect floor_nearest -DAFFINE_UV: differs mistakes=uv_affine
// expect cube_nearest -DAFFINE_UV: differs mistakes=uv_affine
// expect knot_phong -DAFFINE_UV: agree
// expect floor_trilinear -DLOD_ACROSS_ONLY: differs mistakes=lod_one_axis
// expect cube_trilinear -DLOD_ACROSS_ONLY: differs mistakes=lod_one_axis
// expect floor_bilinear -DLOD_ACROSS_ONLY: agree
// expect floor_nearest -DT_DOWN: differs mistakes=t_not_flipped
// expect cube_nearest -DT_DOWN: differs mistakes=t_not_flipped
// expect floor_bilinear -DBIAS_BILINEAR: differs mistakes=bilinear_no_half_texel
// expect cube_bilinear -DBIAS_BILINEAR: differs mistakes=bilinear_no_half_texel
// expect floor_nearest -DBIAS_BILINEAR: agree
// expect-grade: 200
// expect-grade -DAFFINE_UV: texture_nearest=0 texture_bilinear=0 texture_trilinear=0 resize=7 synchronized=9
// expect-grade -DLOD_ACROSS_ONLY: texture_trilinear=0 resize=7 synchronized=12
// expect-grade -DT_DOWN: texture_nearest=0 texture_bilinear=0 texture_trilinear=0 resize=7 synchronized=9
// expect-grade -DBIAS_BILINEAR: texture_bilinear=0 texture_trilinear=0 resize=7 synchronized=11
#define CLOSE2GL_TRACE_IMPLEMENTATION
#include "close2gl_trace.h"
#define CLOSE2GL_RASTER_IMPLEMENTATION   // [trace]
#include "close2gl_raster.h"             // [trace]
#include "rcommon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

using vec3 = std::array<double, 3>;
using vec2 = std::array<double, 2>;

static vec3 operator+(vec3 a, vec3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
static vec3 operator-(vec3 a, vec3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
static vec3 operator*(vec3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
static vec3 operator*(vec3 a, vec3 b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }
static double dot(vec3 a, vec3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static vec3 normalized(vec3 a) { return a * (1 / std::sqrt(dot(a, a))); }

struct Vertex {            // what a corner carries to the rasterizer
    double x, y, z, q;     // window (y up), depth, 1/w
    vec3 rgb, eye, normal;
    vec2 uv;
};

struct ClipVertex {
    std::array<double, 4> clip;
    Vertex v;              // its attributes (x y z q filled after the division)
};

struct Level {
    int w, h;
    std::vector<vec3> texels;   // top row first, in [0, 1]
    vec3 at(long x, long y) const
    {
        auto wrap = [](long i, int n) { return static_cast<int>(((i % n) + n) % n); };
        return texels[static_cast<size_t>(wrap(y, h)) * w + wrap(x, w)];
    }
};

class Rasterizer {
public:
    int W, H, shading, filter;
    bool textured = false;
    vec3 color, lightEye;
    std::vector<unsigned char> frame;   // bottom row first
    std::vector<float> depth;
    std::vector<Level> mips;

    vec3 illuminate(vec3 eye, vec3 normal, bool specular) const
    {
        vec3 n = normalized(normal), toLight = lightEye - eye, l = normalized(toLight);
        vec3 v = normalized(eye * -1.0), r = n * (2 * dot(n, l)) - l;
        double d = std::sqrt(dot(toLight, toLight));
        double att = std::min(1 / (RC_ATT[0] + RC_ATT[1] * d + RC_ATT[2] * d * d), 1.0);
        double lit = RC_KD * std::max(dot(n, l), 0.0);
        if (specular) lit += RC_KS * std::pow(std::max(dot(v, r), 0.0), RC_SHININESS);
        vec3 i;
        for (int k = 0; k < 3; k++) i[k] = RC_IA[k] * RC_KA + RC_IL[k] * att * lit;
        return color * i;
    }

    void buildMips(const unsigned char *rgb, int w, int h)
    {
        Level base{w, h, {}};
        for (int i = 0; i < w * h; i++)
            base.texels.push_back({rgb[3 * i] / 255.0, rgb[3 * i + 1] / 255.0, rgb[3 * i + 2] / 255.0});
        mips.push_back(base);
        while (mips.back().w > 1 || mips.back().h > 1) {
            const Level &a = mips.back();
            Level b{std::max(a.w / 2, 1), std::max(a.h / 2, 1), {}};
            for (int y = 0; y < b.h; y++)
                for (int x = 0; x < b.w; x++) {
                    int x1 = std::min(2 * x + 1, a.w - 1), y1 = std::min(2 * y + 1, a.h - 1);
                    b.texels.push_back((a.at(2 * x, 2 * y) + a.at(x1, 2 * y) + a.at(2 * x, y1) + a.at(x1, y1)) * 0.25);
                }
            mips.push_back(b);
        }
    }

    // (s, t) in texels of a level, from its top-left corner.
    vec2 place(int level, vec2 st) const
    {
#ifdef T_DOWN
        return {st[0] * mips[level].w, st[1] * mips[level].h};   // BUG: t = 0 at the top
#else
        return {st[0] * mips[level].w, (1 - st[1]) * mips[level].h};
#endif
    }

    vec3 bilinear(int level, vec2 st) const
    {
        vec2 p = place(level, st);
#ifndef BIAS_BILINEAR
        p[0] -= 0.5, p[1] -= 0.5;                                  // (without: BUG)
#endif
        double x0 = std::floor(p[0]), y0 = std::floor(p[1]), fx = p[0] - x0, fy = p[1] - y0;
        long x = static_cast<long>(x0), y = static_cast<long>(y0);
        const Level &l = mips[level];
        return (l.at(x, y) * (1 - fx) + l.at(x + 1, y) * fx) * (1 - fy)
               + (l.at(x, y + 1) * (1 - fx) + l.at(x + 1, y + 1) * fx) * fy;
    }

    vec3 sample(vec2 st, double lod) const
    {
        if (filter == C2G_FILTER_NEAREST) {
            vec2 p = place(0, st);
            return mips[0].at(static_cast<long>(std::floor(p[0])), static_cast<long>(std::floor(p[1])));
        }
        if (filter == C2G_FILTER_BILINEAR) return bilinear(0, st);
        int top = static_cast<int>(mips.size()) - 1;
        lod = std::clamp(lod, 0.0, static_cast<double>(top));
        int below = static_cast<int>(std::floor(lod));
        double f = lod - below;
        return bilinear(below, st) * (1 - f) + bilinear(std::min(below + 1, top), st) * f;
    }

    void draw(const std::array<Vertex, 3> &v)
    {
        auto area = [](double ax, double ay, double bx, double by, double cx, double cy) {
            return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
        };
        double whole = area(v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
        if (whole == 0 || !std::isfinite(whole)) return;
        auto weights = [&](double px, double py) {
            return std::array<double, 3>{area(px, py, v[1].x, v[1].y, v[2].x, v[2].y) / whole,
                                         area(v[0].x, v[0].y, px, py, v[2].x, v[2].y) / whole,
                                         area(v[0].x, v[0].y, v[1].x, v[1].y, px, py) / whole};
        };
        auto uvAt = [&](double px, double py) {
            auto w = weights(px, py);
            vec2 st{0, 0};
#ifdef AFFINE_UV
            for (int k = 0; k < 3; k++)   // BUG: the screen's weights, without 1/w
                st[0] += w[k] * v[k].uv[0], st[1] += w[k] * v[k].uv[1];
#else
            double sum = 0;
            for (int k = 0; k < 3; k++) {
                double wq = w[k] * v[k].q;
                st[0] += wq * v[k].uv[0], st[1] += wq * v[k].uv[1], sum += wq;
            }
            st[0] /= sum, st[1] /= sum;
#endif
            return st;
        };
        double xmin = std::min({v[0].x, v[1].x, v[2].x}), xmax = std::max({v[0].x, v[1].x, v[2].x});
        double ymin = std::min({v[0].y, v[1].y, v[2].y}), ymax = std::max({v[0].y, v[1].y, v[2].y});
        int i0 = std::max(0, static_cast<int>(std::floor(std::max(xmin, -1.0))));
        int i1 = std::min(W - 1, static_cast<int>(std::ceil(std::min(xmax, static_cast<double>(W)))));
        int j0 = std::max(0, static_cast<int>(std::floor(std::max(ymin, -1.0))));
        int j1 = std::min(H - 1, static_cast<int>(std::ceil(std::min(ymax, static_cast<double>(H)))));
        for (int j = j0; j <= j1; j++)
            for (int i = i0; i <= i1; i++) {
                double px = i + 0.5, py = j + 0.5;
                auto w = weights(px, py);
                if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
                size_t at = static_cast<size_t>(j) * W + i;
                float z = static_cast<float>(w[0] * v[0].z + w[1] * v[1].z + w[2] * v[2].z);
                if (!(z < depth[at])) continue;
                depth[at] = z;
                double sum = 0;
                vec3 rgb{0, 0, 0}, eye{0, 0, 0}, normal{0, 0, 0};
                for (int k = 0; k < 3; k++) {
                    double wq = w[k] * v[k].q;
                    rgb = rgb + v[k].rgb * wq, eye = eye + v[k].eye * wq, normal = normal + v[k].normal * wq;
                    sum += wq;
                }
                rgb = rgb * (1 / sum), eye = eye * (1 / sum), normal = normal * (1 / sum);
                vec3 c = shading == C2G_SHADING_NONE    ? color
                         : shading == C2G_SHADING_PHONG ? illuminate(eye, normal, true)
                                                        : rgb;
                if (textured) {
                    double lod = 0;
                    if (filter == C2G_FILTER_TRILINEAR) {
                        // the quad: even column, even row from the top; its top-left pixel
                        int left = i & ~1, topRow = (H - 1 - j) & ~1;
                        double qx = left + 0.5, qy = H - 1 - topRow + 0.5;   // y up
                        vec2 a = uvAt(qx, qy), b = uvAt(qx + 1, qy), d = uvAt(qx, qy - 1);
                        double across = std::hypot((b[0] - a[0]) * mips[0].w, (b[1] - a[1]) * mips[0].h);
                        double down = std::hypot((d[0] - a[0]) * mips[0].w, (d[1] - a[1]) * mips[0].h);
#ifdef LOD_ACROSS_ONLY
                        down = 0;                                          // BUG: across only
#endif
                        lod = std::log2(std::max(across, down));
                    }
                    c = c * sample(uvAt(px, py), lod);
                }
                for (int k = 0; k < 3; k++)
                    frame[3 * at + k] = static_cast<unsigned char>(std::clamp(c[k], 0.0, 1.0) * 255 + 0.5);
            }
    }
};

int main(int argc, char **argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s SCENE TRACE\n", argv[0]);
        return 2;
    }
    c2g_scene s;
    rc_mesh m;
    if (!c2g_read_scene(argv[1], &s) || !rc_load(s.model, &m)) return 1;
    double M[16], P[16];
    rc_camera(&s, &m, M, P);
    auto times = [&](const double *A, std::array<double, 4> p) {
        std::array<double, 4> r{};
        for (int row = 0; row < 4; row++)
            for (int k = 0; k < 4; k++) r[row] += A[4 * row + k] * p[k];
        return r;
    };

    Rasterizer r;
    r.W = s.width, r.H = s.height, r.shading = s.shading, r.filter = s.filter;
    r.color = {s.color[0], s.color[1], s.color[2]};
    auto le = times(M, {s.light[0], s.light[1], s.light[2], 1});
    r.lightEye = {le[0], le[1], le[2]};
    bool lit = s.shading != C2G_SHADING_NONE;
    bool gouraud = s.shading == C2G_SHADING_GOURAUD_AD || s.shading == C2G_SHADING_GOURAUD_ADS;
    std::vector<unsigned char> base;
    int tw = 0, th = 0;
    if (s.has_texture && m.textured) {
        unsigned char *px = c2r_read_ppm(s.texture, &tw, &th);
        if (!px) return 1;
        base.assign(px, px + 3 * tw * th);
        std::free(px);
        r.buildMips(base.data(), tw, th);
        r.textured = true;
    }
    unsigned char clear[3];
    for (int k = 0; k < 3; k++) clear[k] = static_cast<unsigned char>(std::clamp(s.background[k], 0.0, 1.0) * 255 + 0.5);
    for (int i = 0; i < r.W * r.H; i++) r.frame.insert(r.frame.end(), clear, clear + 3);
    r.depth.assign(static_cast<size_t>(r.W) * r.H, 1.0f);

    FILE *out = c2r_open(argv[2]);                                      // [trace]
    if (!out) return 1;                                                 // [trace]
    std::string texName = std::string(argv[2]) + ".texture.ppm";       // [trace]
    c2r_write_model(out, rc_base(s.model));                             // [trace]
    c2r_write_window(out, r.W, r.H);                                    // [trace]
    c2r_write_shading(out, s.shading);                                  // [trace]
    c2r_write_color(out, s.color);                                      // [trace]
    c2r_write_background(out, s.background);                            // [trace]
    if (lit) {                                                          // [trace]
        c2r_write_light(out, s.light);                                  // [trace]
        c2r_write_matrix(out, M);                                       // [trace]
        c2r_write_lighting(out, RC_IA, RC_IL, RC_KA, RC_KD, RC_KS, RC_SHININESS, RC_ATT); // [trace]
    }                                                                   // [trace]
    if (r.textured) c2r_write_texture(out, rc_base(texName.c_str()), r.filter); // [trace]
    c2r_write_buffer_names(out, argv[2]);                               // [trace]
    c2r_write_attributes(out, (gouraud ? C2R_RGB : 0) | (lit ? C2R_EYE | C2R_NORMAL : 0) | (r.textured ? C2R_UV : 0)); // [trace]

    for (int t = 0; t < m.count; t++) {
        std::vector<ClipVertex> poly;
        for (int c = 0; c < 3; c++) {
            const rc_tri &tri = m.tri[t];
            auto e = times(M, {tri.p[c][0], tri.p[c][1], tri.p[c][2], 1});
            auto n = times(M, {tri.n[c][0], tri.n[c][1], tri.n[c][2], 0});
            ClipVertex cv{times(P, e), {}};
            cv.v.eye = {e[0], e[1], e[2]}, cv.v.normal = {n[0], n[1], n[2]};
            cv.v.rgb = gouraud ? r.illuminate(cv.v.eye, cv.v.normal, s.shading == C2G_SHADING_GOURAUD_ADS) : r.color;
            cv.v.uv = {tri.uv[c][0], tri.uv[c][1]};
            poly.push_back(cv);
        }
        // the near plane only: z >= -w
        std::vector<ClipVertex> kept;
        for (size_t i = 0; i < poly.size(); i++) {
            const ClipVertex &a = poly[i], &b = poly[(i + 1) % poly.size()];
            double da = a.clip[2] + a.clip[3], db = b.clip[2] + b.clip[3];
            if (da >= 0) kept.push_back(a);
            if ((da >= 0) != (db >= 0)) {
                double f = da / (da - db);
                ClipVertex c;
                for (int k = 0; k < 4; k++) c.clip[k] = a.clip[k] + (b.clip[k] - a.clip[k]) * f;
                c.v.rgb = a.v.rgb + (b.v.rgb - a.v.rgb) * f, c.v.eye = a.v.eye + (b.v.eye - a.v.eye) * f;
                c.v.normal = a.v.normal + (b.v.normal - a.v.normal) * f;
                c.v.uv = {a.v.uv[0] + (b.v.uv[0] - a.v.uv[0]) * f, a.v.uv[1] + (b.v.uv[1] - a.v.uv[1]) * f};
                kept.push_back(c);
            }
        }
        if (kept.size() < 3) continue;
        std::vector<Vertex> win;
        double area = 0;
        for (auto &c : kept) {
            Vertex v = c.v;
            v.q = 1 / c.clip[3];
            v.x = (c.clip[0] * v.q + 1) * r.W / 2, v.y = (c.clip[1] * v.q + 1) * r.H / 2;
            v.z = c.clip[2] * v.q * 0.5 + 0.5;
            win.push_back(v);
        }
        for (size_t i = 0; i < win.size(); i++)
            area += win[i].x * win[(i + 1) % win.size()].y - win[(i + 1) % win.size()].x * win[i].y;
        if ((s.culling == C2G_CULL_CCW && area <= 0) || (s.culling == C2G_CULL_CW && area >= 0)) continue;
        for (size_t i = 1; i + 1 < win.size(); i++) {
            std::array<Vertex, 3> tri{win[0], win[i], win[i + 1]};
            std::vector<double> nums;                                   // [trace]
            for (auto &v : tri) {                                       // [trace]
                nums.insert(nums.end(), {v.x, v.y, v.z, v.q});          // [trace]
                if (gouraud) nums.insert(nums.end(), v.rgb.begin(), v.rgb.end()); // [trace]
                if (lit) nums.insert(nums.end(), v.eye.begin(), v.eye.end()); // [trace]
                if (lit) nums.insert(nums.end(), v.normal.begin(), v.normal.end()); // [trace]
                if (r.textured) nums.insert(nums.end(), v.uv.begin(), v.uv.end()); // [trace]
            }                                                           // [trace]
            c2r_write_tri(out, t, nums.data());                         // [trace]
            r.draw(tri);
        }
    }
    if (!c2r_close(out)) return 1;                                      // [trace]
    if (!c2r_write_buffers(argv[2], r.frame.data(), r.depth.data(), r.W, r.H, C2R_BOTTOM_ROW_FIRST)) // [trace]
        return 1;                                                       // [trace]
    if (r.textured && !c2r_write_ppm(texName.c_str(), base.data(), tw, th, C2R_TOP_ROW_FIRST)) // [trace]
        return 1;                                                       // [trace]
    return 0;
}
