// cpp_glm.cpp: a C++ program with glm, float32, as most students of the course write it: glm's
// column-major mat4 and vec4, the Close2GL matrices built by hand (glm::lookAt and
// glm::frustum only as a reference: it warns when its own M or P strays from them), the
// assignment's simple clipping with glm::vec4 clip coordinates, 2D output in window pixels y up,
// culling by the winding on screen.
//
//     cpp_glm SCENE TRACE
//
// Variant: -DYDOWN draws in window pixels with y down (gluOrtho2D(0, W, H, 0)) and tests the
// winding of those numbers as they are ("culling in window coordinates"): a triangle that is
// counter-clockwise on screen is clockwise in them, so it culls by the opposite winding of its
// numbers and says so (`culling cw window` for a scene's `culling ccw`).
//
// Lines ending in "[trace]" were added only to write the trace.
//
// expect cube_front: agree
// expect knot_turned: agree
// expect knot_cw: agree
// expect far_offset_turned: agree
// expect knot_turned -DYDOWN: agree
// expect knot_cw -DYDOWN: agree
// expect far_offset_turned -DYDOWN: agree
// expect-grade cube: 200
// expect-grade cube -DYDOWN: 200
#define CLOSE2GL_FLOAT                // [trace]
#define CLOSE2GL_TRACE_IMPLEMENTATION // [trace]
#include "close2gl_trace.h"
#include "model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

struct Camera {
    glm::vec3 eye, u, v, n;
    float hfov, vfov, znear, zfar;

    glm::mat4 modelview() const {
        glm::mat4 m(1.0f);  // m[column][row]
        for (int i = 0; i < 3; i++) m[i][0] = u[i], m[i][1] = v[i], m[i][2] = n[i];
        m[3] = glm::vec4(-glm::dot(u, eye), -glm::dot(v, eye), -glm::dot(n, eye), 1.0f);
        return m;
    }
    glm::mat4 projection() const {
        float r = znear * std::tan(glm::radians(hfov) / 2), t = znear * std::tan(glm::radians(vfov) / 2);
        glm::mat4 p(0.0f);
        p[0][0] = znear / r, p[1][1] = znear / t;
        p[2][2] = -(zfar + znear) / (zfar - znear), p[3][2] = -2 * zfar * znear / (zfar - znear);
        p[2][3] = -1;
        return p;
    }
    void turn(glm::vec3 &a, glm::vec3 &b, float degrees) {
        float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
        glm::vec3 a0 = a;
        a = c * a0 + s * b;
        b = c * b - s * a0;
    }
    void apply(const c2g_motion &m, glm::vec3 target) {
        glm::vec3 &axis = m.axis == 'u' ? u : m.axis == 'v' ? v : n;
        if (m.kind == 'r') {
            if (m.axis == 'u') turn(v, n, m.amount);
            if (m.axis == 'v') turn(n, u, m.amount);
            if (m.axis == 'n') turn(u, v, m.amount);
            return;
        }
        eye += m.amount * axis;
        if (m.kind != 'o') return;
        n = glm::normalize(eye - target);
        if (m.axis == 'u') u = glm::normalize(glm::cross(v, n)), v = glm::cross(n, u);
        else v = glm::normalize(glm::cross(n, u)), u = glm::cross(v, n);
    }
};

static float largest_difference(const glm::mat4 &a, const glm::mat4 &b) {
    float d = 0;
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) d = std::max(d, std::abs(a[c][r] - b[c][r]) / (1 + std::abs(b[c][r])));
    return d;
}

int main(int argc, char **argv) {
    if (argc != 3) return 2;
    c2g_scene s;
    double *xyz;
    int count;
    if (!c2g_read_scene(argv[1], &s) || !(count = load_model(s.model, &xyz))) return 1;
    std::vector<glm::vec3> p(3 * (size_t)count);
    for (size_t i = 0; i < p.size(); i++) p[i] = glm::vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    glm::vec3 lo = p[0], hi = p[0];
    for (const glm::vec3 &q : p) lo = glm::min(lo, q), hi = glm::max(hi, q);
    glm::vec3 centre = (lo + hi) * 0.5f;
    float radius = glm::length(hi - lo) / 2;

    Camera cam;
    cam.hfov = s.hfov, cam.vfov = s.vfov;
    if (s.framed) {
        float d = radius / std::sin(glm::radians(std::min(s.hfov, s.vfov)) / 2);
        cam.eye = centre + glm::vec3(0, 0, d);
        cam.u = {1, 0, 0}, cam.v = {0, 1, 0}, cam.n = {0, 0, 1};
        cam.znear = s.has_near ? s.znear : (d - radius) / 2;
        cam.zfar = s.has_far ? s.zfar : d + 2 * radius;
    } else {
        cam.eye = glm::vec3(s.position[0], s.position[1], s.position[2]);
        cam.u = glm::vec3(s.u[0], s.u[1], s.u[2]);
        cam.v = glm::vec3(s.v[0], s.v[1], s.v[2]);
        cam.n = glm::vec3(s.n[0], s.n[1], s.n[2]);
        cam.znear = s.znear, cam.zfar = s.zfar;
    }
    glm::vec3 target = s.has_lookat ? glm::vec3(s.lookat[0], s.lookat[1], s.lookat[2]) : centre;
    for (int i = 0; i < s.motion_count; i++) cam.apply(s.motions[i], target);

    glm::mat4 M = cam.modelview(), P = cam.projection(), PM = P * M;
    float r = cam.znear * std::tan(glm::radians(cam.hfov) / 2), t = cam.znear * std::tan(glm::radians(cam.vfov) / 2);
    if (largest_difference(M, glm::lookAt(cam.eye, cam.eye - cam.n, cam.v)) > 1e-4f
        || largest_difference(P, glm::frustum(-r, r, -t, t, cam.znear, cam.zfar)) > 1e-4f)
        std::fprintf(stderr, "warning: M or P differs from glm's\n");
#ifdef YDOWN
    const float top = 0, bottom = (float)s.height;  // gluOrtho2D(0, W, H, 0)
    const int flip = -1;
#else
    const float top = (float)s.height, bottom = 0;
    const int flip = 1;
#endif

    FILE *f = std::fopen(argv[2], "w");                                          // [trace]
    if (!f) return 1;                                                            // [trace]
    c2g_write_header(f);                                                         // [trace]
    c2g_write_window(f, s.width, s.height);                                      // [trace]
    c2g_write_ortho2d(f, 0, (float)s.width, bottom, top);                        // [trace]
    c2g_write_camera(f, &cam.eye.x, &cam.u.x, &cam.v.x, &cam.n.x, cam.hfov, cam.vfov, cam.znear, cam.zfar); // [trace]
    int declared = flip > 0 || s.culling == C2G_CULL_OFF ? s.culling : s.culling == C2G_CULL_CCW ? C2G_CULL_CW : C2G_CULL_CCW; // [trace]
    c2g_write_culling_in(f, declared, flip > 0 ? C2G_CULL_ON_SCREEN : C2G_CULL_IN_WINDOW); // [trace]
    c2g_write_glm(f, 'M', M);                                                    // [trace]
    c2g_write_glm(f, 'P', P);                                                    // [trace]
    c2g_real V[16] = {s.width / 2.0f, 0, 0, s.width / 2.0f, 0, flip * s.height / 2.0f, 0, s.height / 2.0f, // [trace]
                      0, 0, 0.5f, 0.5f, 0, 0, 0, 1};                             // [trace]
    c2g_write_matrix(f, 'V', V);                                                 // [trace]
    c2g_write_mode(f, s.mode);                                                   // [trace]
    for (int tri = 0; tri < count; tri++) {
        glm::vec4 clip[3];
        glm::vec2 win[3];
        bool inside = true;
        for (int k = 0; k < 3; k++) {
            clip[k] = PM * glm::vec4(p[3 * tri + k], 1.0f);
            for (int a = 0; a < 3; a++) inside = inside && std::abs(clip[k][a]) <= clip[k].w;
        }
        for (int k = 0; k < 3 && inside; k++)
            win[k] = glm::vec2((clip[k].x / clip[k].w + 1) * s.width / 2,
                               bottom + (clip[k].y / clip[k].w + 1) * (top - bottom) / 2);
        glm::vec2 e1 = win[1] - win[0], e2 = win[2] - win[0];
        float area = inside ? e1.x * e2.y - e1.y * e2.x : 0;  // counter-clockwise in these numbers: > 0
        bool front = s.culling == C2G_CULL_CCW ? flip * area > 0 : flip * area < 0;
        bool drawn = inside && (s.culling == C2G_CULL_OFF || front);
        c2g_write_triangle(f, tri, &clip[0].x, drawn ? &win[0].x : nullptr, 3, 2); // [trace]
    }
    c2g_write_end(f);                                                            // [trace]
    std::fclose(f);                                                              // [trace]
    std::free(xyz);
    c2g_free_scene(&s);
    return 0;
}
