// Camera matrices in double precision (see camera.hpp).
#include "ssfx/scene/camera.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "ssfx/core/error.hpp"
#include "ssfx/io/camera.hpp"

namespace ssfx::scene {

glm::mat4 CameraSetup::viewProjectionF() const { return glm::mat4(projection * view); }

glm::dmat4 lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    const glm::dvec3 d = target - eye;
    if (!(glm::length(d) > 0.0)) throw Error("view: eye and target are the same point");
    const glm::dvec3 f = glm::normalize(d);
    const glm::dvec3 c = glm::cross(f, up);
    if (!(glm::length(c) > 1e-9 * glm::length(up))) throw Error("view: 'up' is zero or parallel to the view direction");
    const glm::dvec3 s = glm::normalize(c);
    const glm::dvec3 u = glm::cross(s, f);
    glm::dmat4 m(1.0);  // rows s, u, -f (column-major storage: m[column][row])
    for (int i = 0; i < 3; ++i) {
        m[i][0] = s[i];
        m[i][1] = u[i];
        m[i][2] = -f[i];
    }
    m[3][0] = -glm::dot(s, eye);
    m[3][1] = -glm::dot(u, eye);
    m[3][2] = glm::dot(f, eye);
    return m;
}

glm::dmat4 perspective(double fovY, double aspect, double zNear, double zFar) {
    if (!(fovY > 0.0 && fovY < std::numbers::pi))
        throw Error(fmt::format("camera: fov {} rad is not in (0, pi)", fovY));
    if (!(aspect > 0.0 && std::isfinite(aspect))) throw Error(fmt::format("camera: aspect {} is not positive", aspect));
    if (!(zNear > 0.0 && std::isfinite(zNear))) throw Error(fmt::format("camera: z_near {} must be > 0", zNear));
    if (!(zFar > zNear)) throw Error(fmt::format("camera: z_far {} must be > z_near {} (or infinite)", zFar, zNear));
    const double f = 1.0 / std::tan(fovY / 2.0);
    glm::dmat4 p(0.0);
    p[0][0] = f / aspect;
    p[1][1] = -f;  // Vulkan: y_ndc = -1 is the top row
    p[2][3] = -1.0;
    // d = z_clip / w_clip with w_clip = -z. Solving d(-n) = 0, d(-far) = 1 gives
    // d = far (z + n) / (z (far - n)) (the inverse of sao.md eq. 2 with z_n = -n, z_f = -far);
    // for far -> infinity, d = 1 + n / z.
    if (std::isinf(zFar)) {
        p[2][2] = -1.0;
        p[3][2] = -zNear;
    } else {
        p[2][2] = -zFar / (zFar - zNear);
        p[3][2] = -zFar * zNear / (zFar - zNear);
    }
    return p;
}

CameraSetup cameraSetup(const View& view, int width, int height, int guard) {
    checkDimensions(width, height, "render size");
    if (guard < 0 || guard > 4096) throw Error(fmt::format("guard band {} is not in [0, 4096]", guard));
    CameraSetup c;
    c.width = width;
    c.height = height;
    c.guard = guard;
    checkDimensions(c.bufferWidth(), c.bufferHeight(), "render size with guard band");
    const double fovY = view.fovYDeg * std::numbers::pi / 180.0;
    if (!(fovY > 0.0 && fovY < std::numbers::pi))
        throw Error(fmt::format("view: fov_y_deg {} is not in (0, 180)", view.fovYDeg));
    // Same pixel size in the widened buffer: tan(fov'/2) = tan(fov/2) (h + 2g) / h.
    const double fovYBuffer = 2.0 * std::atan(std::tan(fovY / 2.0) * c.bufferHeight() / height);
    c.view = lookAt(view.eye, view.target, view.up);
    c.projection = perspective(fovYBuffer, double(c.bufferWidth()) / c.bufferHeight(), view.zNear, view.zFar);
    c.camera.zNear = -view.zNear;
    c.camera.zFar = std::isinf(view.zFar) ? -INFINITY : -view.zFar;
    c.camera.fovY = fovYBuffer;
    ssfx::projection(c.camera, c.bufferWidth(), c.bufferHeight());  // the AO code's own validation
    return c;
}

std::string cameraSetupJson(const CameraSetup& s) {
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(io::cameraJson(s.camera));
    j["width"] = s.width;
    j["height"] = s.height;
    j["guard"] = s.guard;
    auto rows = [](const glm::dmat4& m) {
        nlohmann::ordered_json r = nlohmann::ordered_json::array();
        for (int row = 0; row < 4; ++row) r.push_back({m[0][row], m[1][row], m[2][row], m[3][row]});
        return r;
    };
    j["projection"] = rows(s.projection);
    j["view"] = rows(s.view);
    return j.dump(2) + "\n";
}

}  // namespace ssfx::scene
