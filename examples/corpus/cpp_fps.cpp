// cpp_fps.cpp: a first-person camera in C++ with glm, float32: the camera is a position, a yaw
// and a pitch about the world's up (+y), and its axes are recomputed from the two angles each
// frame, as games do (front from yaw and pitch, right = front x up, up = right x front). It can
// turn only about the world's up and its own u, so it runs on scenes whose turns are `rotate v`
// before `rotate u`; it starts from `camera framed` (yaw 0, pitch 0: looking along -z) or from a
// given pose without roll (its yaw and pitch; `orbit` and `rotate n` it ignores). It
// draws in window pixels, y up, with the assignment's simple clipping and culling by the winding
// on screen.
//
//     cpp_fps SCENE TRACE
//
// It writes the axes it built M from, as it holds them. Variant: -DRIGHT_NOT_NORMALIZED forgets
// to normalize right = front x up, whose length is cos(pitch), so that M's first two rows are
// cos(pitch) of their length; it writes its axes normalized (what it believes its camera is).
//
// Lines ending in "[trace]" were added only to write the trace.
//
// expect knot_fps: agree
// expect far_away_fps: agree
// expect far_offset_fps: agree
// expect knot_fps -DRIGHT_NOT_NORMALIZED: differs stage=M unexplained
// expect far_offset_fps -DRIGHT_NOT_NORMALIZED: differs stage=M unexplained
// expect-grade cube: lookat_translation=0 rotation=10
// expect-grade cube -DRIGHT_NOT_NORMALIZED: translation=0 lookat_translation=0 rotation=10 synchronized=14
#define CLOSE2GL_FLOAT                // [trace]
#define CLOSE2GL_TRACE_IMPLEMENTATION // [trace]
#include "close2gl_trace.h"
#include "model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>

namespace {

const glm::vec3 world_up(0, 1, 0);

struct FpsCamera {
    glm::vec3 position;
    float yaw = 0, pitch = 0;  // degrees: yaw turns left about +y, pitch tilts up
    float fov_x = 60, fov_y = 60, near_plane = 0.1f, far_plane = 100;

    glm::vec3 front() const {
        float y = glm::radians(yaw), p = glm::radians(pitch);
        return glm::vec3(-std::sin(y) * std::cos(p), std::sin(p), -std::cos(y) * std::cos(p));
    }
    // The axes of this frame: right (u), up (v) and back (n).
    void axes(glm::vec3 &right, glm::vec3 &up, glm::vec3 &back) const {
        glm::vec3 f = front();
#ifdef RIGHT_NOT_NORMALIZED
        right = glm::cross(f, world_up);
#else
        right = glm::normalize(glm::cross(f, world_up));
#endif
        up = glm::cross(right, f);
        back = -f;
    }
    glm::mat4 view() const {
        glm::vec3 r, u, b;
        axes(r, u, b);
        return glm::transpose(glm::mat4(glm::vec4(r, -glm::dot(r, position)), glm::vec4(u, -glm::dot(u, position)),
                                        glm::vec4(b, -glm::dot(b, position)), glm::vec4(0, 0, 0, 1)));
    }
    glm::mat4 projection() const {
        float sx = 1 / std::tan(glm::radians(fov_x / 2)), sy = 1 / std::tan(glm::radians(fov_y / 2));
        float a = (far_plane + near_plane) / (near_plane - far_plane), b = 2 * far_plane * near_plane / (near_plane - far_plane);
        return glm::mat4(sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, a, -1, 0, 0, b, 0);  // column by column
    }
};

}  // namespace

int main(int argc, char **argv) {
    if (argc != 3) return 2;
    c2g_scene s;
    double *raw;
    int count;
    if (!c2g_read_scene(argv[1], &s) || !(count = load_model(s.model, &raw))) return 1;
    std::vector<glm::vec3> vertices;
    for (int i = 0; i < 3 * count; i++) vertices.emplace_back(raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (auto &q : vertices) lo = glm::min(lo, q), hi = glm::max(hi, q);
    float radius = glm::length(hi - lo) / 2, distance = radius / std::sin(glm::radians(std::min(s.hfov, s.vfov) / 2));

    FpsCamera cam;
    cam.position = (lo + hi) / 2.0f + glm::vec3(0, 0, distance);
    cam.fov_x = s.hfov, cam.fov_y = s.vfov;
    cam.near_plane = s.has_near ? s.znear : (distance - radius) / 2;
    cam.far_plane = s.has_far ? s.zfar : distance + 2 * radius;
    if (!s.framed) {  // a given pose: its yaw and pitch from where it looks (a roll is lost)
        cam.position = glm::vec3(s.position[0], s.position[1], s.position[2]);
        cam.yaw = glm::degrees(std::atan2(s.n[0], s.n[2]));
        cam.pitch = glm::degrees(std::asin(glm::clamp(-s.n[1], -1.0f, 1.0f)));
        cam.near_plane = s.znear, cam.far_plane = s.zfar;
    }
    for (int i = 0; i < s.motion_count; i++) {
        const c2g_motion &m = s.motions[i];
        glm::vec3 r, u, b;
        cam.axes(r, u, b);
        if (m.kind == 'm') cam.position += m.amount * glm::normalize(m.axis == 'u' ? r : m.axis == 'v' ? u : b);
        else if (m.kind == 'r' && m.axis == 'v') cam.yaw += m.amount;
        else if (m.kind == 'r' && m.axis == 'u') cam.pitch = std::clamp(cam.pitch + m.amount, -89.0f, 89.0f);
        else std::fprintf(stderr, "%s: a first-person camera ignores '%c %c'\n", argv[1], m.kind, m.axis);
    }

    glm::mat4 M = cam.view(), P = cam.projection(), PM = P * M;
    glm::vec3 u, v, n;                                                           // [trace]
    cam.axes(u, v, n);                                                           // [trace]
#ifdef RIGHT_NOT_NORMALIZED
    u = glm::normalize(u), v = glm::normalize(v);                                // [trace: variant]
#endif
    FILE *out = std::fopen(argv[2], "w");                                        // [trace]
    if (!out) return 1;                                                          // [trace]
    c2g_write_header(out);                                                       // [trace]
    c2g_write_window(out, s.width, s.height);                                    // [trace]
    c2g_write_camera(out, &cam.position.x, &u.x, &v.x, &n.x, cam.fov_x, cam.fov_y, cam.near_plane, cam.far_plane); // [trace]
    c2g_write_culling(out, s.culling);                                           // [trace]
    c2g_write_glm(out, 'M', M);                                                  // [trace]
    c2g_write_glm(out, 'P', P);                                                  // [trace]
    c2g_real V[16] = {s.width / 2.0f, 0, 0, s.width / 2.0f, 0, s.height / 2.0f, 0, s.height / 2.0f, // [trace]
                      0, 0, 0.5f, 0.5f, 0, 0, 0, 1};                             // [trace]
    c2g_write_matrix(out, 'V', V);                                               // [trace]
    c2g_write_mode(out, s.mode);                                                 // [trace]
    for (int t = 0; t < count; t++) {
        glm::vec4 c[3];
        float screen[6];
        bool keep = true;
        for (int k = 0; k < 3; k++) {
            c[k] = PM * glm::vec4(vertices[3 * t + k], 1);
            keep = keep && std::abs(c[k].x) <= c[k].w && std::abs(c[k].y) <= c[k].w && std::abs(c[k].z) <= c[k].w;
        }
        for (int k = 0; k < 3 && keep; k++) {
            screen[2 * k] = (c[k].x / c[k].w * 0.5f + 0.5f) * s.width;
            screen[2 * k + 1] = (c[k].y / c[k].w * 0.5f + 0.5f) * s.height;
        }
        if (keep && s.culling != C2G_CULL_OFF) {
            float twice = (screen[2] - screen[0]) * (screen[5] - screen[1]) - (screen[4] - screen[0]) * (screen[3] - screen[1]);
            keep = s.culling == C2G_CULL_CCW ? twice > 0 : twice < 0;
        }
        c2g_write_triangle(out, t, &c[0].x, keep ? screen : nullptr, 3, 2);     // [trace]
    }
    c2g_write_end(out);                                                          // [trace]
    std::fclose(out);                                                            // [trace]
    std::free(raw);
    c2g_free_scene(&s);
    return 0;
}
