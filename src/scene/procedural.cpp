// The built-in procedural scenes (scene.hpp): a Cornell box, and an "atrium" whose
// columns, arches, stairs, thin bars, folded curtain and checker/brick textures exercise
// texture filtering and ambient occlusion at many scales without any external asset.
#include <cmath>
#include <functional>
#include <numbers>

#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

namespace {

constexpr double kPi = std::numbers::pi;

class MeshBuilder {
public:
    explicit MeshBuilder(Scene& scene) : s_(scene) {}

    std::uint32_t material(const std::string& name, glm::vec3 diffuse, int layer = -1) {
        s_.materials.push_back({name, diffuse, layer});
        return std::uint32_t(s_.materials.size() - 1);
    }

    //! A parallelogram origin + [0,1] eu + [0,1] ev whose normal points along `facing`;
    //! texture coordinates in metres times uvPerMetre.
    void quad(glm::vec3 origin, glm::vec3 eu, glm::vec3 ev, glm::vec3 facing, std::uint32_t mat,
              float uvPerMetre = 1.0f) {
        if (glm::dot(glm::cross(eu, ev), facing) < 0.0f) std::swap(eu, ev);
        const glm::vec3 n = glm::normalize(glm::cross(eu, ev));
        const float lu = glm::length(eu) * uvPerMetre, lv = glm::length(ev) * uvPerMetre;
        const auto base = std::uint32_t(s_.vertices.size());
        s_.vertices.push_back({origin, n, {0, 0}, mat});
        s_.vertices.push_back({origin + eu, n, {lu, 0}, mat});
        s_.vertices.push_back({origin + eu + ev, n, {lu, lv}, mat});
        s_.vertices.push_back({origin + ev, n, {0, lv}, mat});
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) s_.indices.push_back(base + i);
    }

    //! A box with its base centred at `base`, size (sx, sy, sz), turned by `yaw` radians about y.
    void box(glm::vec3 base, glm::vec3 size, std::uint32_t mat, float yaw = 0.0f, float uvPerMetre = 1.0f) {
        const glm::vec3 ax(std::cos(yaw), 0, -std::sin(yaw)), ay(0, 1, 0), az(std::sin(yaw), 0, std::cos(yaw));
        const glm::vec3 ex = ax * size.x, ey = ay * size.y, ez = az * size.z;
        const glm::vec3 o = base - 0.5f * ex - 0.5f * ez;  // the (-x, bottom, -z) corner
        quad(o, ex, ez, -ay, mat, uvPerMetre);
        quad(o + ey, ex, ez, ay, mat, uvPerMetre);
        quad(o, ex, ey, -az, mat, uvPerMetre);
        quad(o + ez, ex, ey, az, mat, uvPerMetre);
        quad(o, ez, ey, -ax, mat, uvPerMetre);
        quad(o + ex, ez, ey, ax, mat, uvPerMetre);
    }

    //! A parametric surface p(u, v), (u, v) in [0, 1]^2, as an nu x nv grid; normals from
    //! the cross product of central differences, towards `outwards(p)` when given.
    void surface(const std::function<glm::dvec3(double, double)>& p, int nu, int nv, std::uint32_t mat,
                 glm::vec2 uvScale, const std::function<glm::dvec3(glm::dvec3)>& outwards) {
        const auto base = std::uint32_t(s_.vertices.size());
        const double h = 1e-4;
        for (int j = 0; j <= nv; ++j)
            for (int i = 0; i <= nu; ++i) {
                const double u = double(i) / nu, v = double(j) / nv;
                const glm::dvec3 pos = p(u, v);
                const glm::dvec3 du = p(std::min(u + h, 1.0), v) - p(std::max(u - h, 0.0), v);
                const glm::dvec3 dv = p(u, std::min(v + h, 1.0)) - p(u, std::max(v - h, 0.0));
                glm::dvec3 n = glm::normalize(glm::cross(du, dv));
                if (glm::dot(n, outwards(pos)) < 0.0) n = -n;
                s_.vertices.push_back(
                    {glm::vec3(pos), glm::vec3(n), glm::vec2(float(u) * uvScale.x, float(v) * uvScale.y), mat});
            }
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const std::uint32_t a = base + std::uint32_t(j * (nu + 1) + i), b = a + 1,
                                    c = a + std::uint32_t(nu + 1), d = c + 1;
                // Wind each triangle so its geometric normal agrees with the vertex normal.
                const glm::vec3 g = glm::cross(s_.vertices[b].position - s_.vertices[a].position,
                                               s_.vertices[d].position - s_.vertices[a].position);
                if (glm::dot(g, s_.vertices[a].normal) >= 0.0f) {
                    for (std::uint32_t k : {a, b, d, a, d, c}) s_.indices.push_back(k);
                } else {
                    for (std::uint32_t k : {a, d, b, a, c, d}) s_.indices.push_back(k);
                }
            }
    }

    void cylinder(glm::dvec3 base, double radius, double height, std::uint32_t mat, int segments = 24) {
        surface(
            [=](double u, double v) {
                return base + glm::dvec3(radius * std::cos(2 * kPi * u), height * v, radius * std::sin(2 * kPi * u));
            },
            segments, 4, mat, {float(2 * kPi * radius), float(height)},
            [=](glm::dvec3 q) { return glm::dvec3(q.x - base.x, 0, q.z - base.z); });
    }

private:
    Scene& s_;
};

// Deterministic small hash for texture variation.
std::uint32_t hash2(std::uint32_t x, std::uint32_t y) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}

ImageRgba8 checkerTexture(int size, int squares) {
    ImageRgba8 t(size, size);
    const int cell = size / squares;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool dark = ((x / cell) + (y / cell)) % 2 == 1;
            t(x, y) = dark ? Rgba8{40, 44, 52, 255} : Rgba8{225, 220, 205, 255};
        }
    return t;
}

ImageRgba8 brickTexture(int size) {
    ImageRgba8 t(size, size);
    const int bw = size / 4, bh = size / 8, mortar = std::max(1, size / 64);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int row = y / bh;
            const int xs = (x + (row % 2) * bw / 2) % size;
            const bool isMortar = (y % bh) < mortar || (xs % bw) < mortar;
            if (isMortar) {
                t(x, y) = {190, 185, 175, 255};
            } else {
                const int v = int(hash2(std::uint32_t(xs / bw), std::uint32_t(row)) % 40);
                t(x, y) = {std::uint8_t(150 + v), std::uint8_t(62 + v / 2), std::uint8_t(45 + v / 3), 255};
            }
        }
    return t;
}

View makeView(glm::dvec3 eye, glm::dvec3 target, double fov = 60.0) {
    View v;
    v.eye = eye;
    v.target = target;
    v.fovYDeg = fov;
    return v;
}

}  // namespace

Scene cornellBox() {
    Scene s;
    s.name = "cornell";
    MeshBuilder b(s);
    const auto white = b.material("white", {0.73f, 0.73f, 0.73f});
    const auto red = b.material("red", {0.63f, 0.065f, 0.05f});
    const auto green = b.material("green", {0.14f, 0.45f, 0.09f});
    // A 2 m box, open towards +z: x in [0, 2], y in [0, 2], z in [-2, 0].
    b.quad({0, 0, 0}, {2, 0, 0}, {0, 0, -2}, {0, 1, 0}, white);       // floor
    b.quad({0, 2, 0}, {2, 0, 0}, {0, 0, -2}, {0, -1, 0}, white);      // ceiling
    b.quad({0, 0, -2}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, white);       // back
    b.quad({0, 0, 0}, {0, 0, -2}, {0, 2, 0}, {1, 0, 0}, red);         // left
    b.quad({2, 0, 0}, {0, 0, -2}, {0, 2, 0}, {-1, 0, 0}, green);      // right
    b.box({0.68f, 0.0f, -0.62f}, {0.6f, 0.6f, 0.6f}, white, -0.31f);  // short box
    b.box({1.32f, 0.0f, -1.32f}, {0.6f, 1.2f, 0.6f}, white, 0.30f);   // tall box
    s.lights.push_back({Light::Type::Point, {1.0f, 1.9f, -1.0f}, glm::vec3(1.6f)});
    s.ambient = glm::vec3(0.12f);
    s.background = glm::vec3(0.0f);
    s.views.emplace_back("front", makeView({1.0, 1.0, 3.0}, {1.0, 1.0, -1.0}, 39.3));
    s.views.emplace_back("corner", makeView({0.25, 1.7, -0.25}, {1.6, 0.3, -1.7}, 60.0));
    return s;
}

Scene atrium() {
    Scene s;
    s.name = "atrium";
    MeshBuilder b(s);
    const int checker = addTextureLayer(s.textures, checkerTexture(256, 8));
    const int brick = addTextureLayer(s.textures, brickTexture(256));
    const auto floorMat = b.material("floor", {1.0f, 1.0f, 1.0f}, checker);
    const auto brickMat = b.material("brick", {1.0f, 1.0f, 1.0f}, brick);
    const auto stone = b.material("stone", {0.78f, 0.75f, 0.68f});
    const auto plaster = b.material("plaster", {0.86f, 0.82f, 0.72f});
    const auto metal = b.material("metal", {0.22f, 0.22f, 0.24f});
    const auto cloth = b.material("curtain", {0.70f, 0.10f, 0.12f});
    const auto steps = b.material("steps", {0.62f, 0.62f, 0.60f}, checker);

    // Floor 20 m x 12 m (x in [-10, 10], z in [-6, 6]); one checker tile per 2 m (0.25 m squares).
    b.quad({-10, 0, 6}, {20, 0, 0}, {0, 0, -12}, {0, 1, 0}, floorMat, 0.5f);
    // Brick walls on both long sides, plaster at the far end; open sky above and behind the camera.
    b.quad({-10, 0, -6}, {20, 0, 0}, {0, 9, 0}, {0, 0, 1}, brickMat, 0.5f);
    b.quad({-10, 0, 6}, {20, 0, 0}, {0, 9, 0}, {0, 0, -1}, brickMat, 0.5f);
    b.quad({10, 0, -6}, {0, 0, 12}, {0, 9, 0}, {-1, 0, 0}, plaster, 0.5f);

    const double springY = 4.25, archR = 1.15, wallTop = springY + archR + 0.6;
    for (double zc : {-3.0, 3.0}) {
        // Six columns with plinths and capitals.
        for (int i = 0; i < 6; ++i) {
            const double xc = -7.5 + 3.0 * i;
            b.box({float(xc), 0.0f, float(zc)}, {0.9f, 0.3f, 0.9f}, stone);
            b.cylinder({xc, 0.3, zc}, 0.35, 3.7, stone);
            b.box({float(xc), 4.0f, float(zc)}, {0.9f, 0.25f, 0.9f}, stone);
        }
        // Semicircular arches between neighbouring columns: the intrados (a half cylinder)
        // and the two planar spandrel faces, ruled from the intrados to the bay's rectangle.
        for (int i = 0; i < 5; ++i) {
            const double xm = -6.0 + 3.0 * i;
            b.surface(
                [=](double u, double v) {
                    const double t = kPi * u;
                    return glm::dvec3(xm + archR * std::cos(t), springY + archR * std::sin(t), zc - 0.3 + 0.6 * v);
                },
                24, 1, stone, {3.6f, 0.6f}, [=](glm::dvec3 q) { return glm::dvec3(xm - q.x, springY - q.y, 0); });
            for (double face : {-0.3, 0.3}) {
                b.surface(
                    [=](double u, double v) {
                        const double t = kPi * u;
                        const glm::dvec2 inner(xm + archR * std::cos(t), springY + archR * std::sin(t));
                        // The bay outline at the same angle: sides x = xm +- 1.5, top y = wallTop.
                        const glm::dvec2 dir(std::cos(t), std::sin(t));
                        double k = 1e9;
                        if (std::abs(dir.x) > 1e-9) k = std::min(k, 1.5 / std::abs(dir.x));
                        if (dir.y > 1e-9) k = std::min(k, (wallTop - springY) / dir.y);
                        const glm::dvec2 outer = glm::dvec2(xm, springY) + k * dir;
                        const glm::dvec2 q = inner + (outer - inner) * v;
                        return glm::dvec3(q.x, q.y, zc + face);
                    },
                    24, 1, stone, {3.0f, 1.0f}, [=](glm::dvec3) { return glm::dvec3(0, 0, face); });
            }
        }
        // Entablature over the colonnade, a balcony floor, and a railing of thin bars.
        b.box({0.0f, float(wallTop), float(zc)}, {15.9f, 0.4f, 0.6f}, stone);
        const float railY = float(wallTop + 0.4);
        for (int k = 0; k <= 104; ++k) b.box({-7.8f + 0.15f * float(k), railY, float(zc)}, {0.03f, 0.9f, 0.03f}, metal);
        b.box({0.0f, railY + 0.9f, float(zc)}, {15.7f, 0.05f, 0.06f}, metal);
    }
    // Stairs rising towards the far wall.
    for (int i = 0; i < 10; ++i) {
        const float x0 = 6.5f + 0.3f * float(i);
        b.box({(x0 + 10.0f) / 2.0f, 0.0f, 0.0f}, {10.0f - x0, 0.18f * float(i + 1), 3.0f}, steps, 0.0f, 0.5f);
    }
    // A curtain hanging in front of the left wall, folds deepening towards the hem.
    b.surface(
        [](double u, double v) {
            const double x = -4.5 + 3.0 * u, y = 4.0 - 3.7 * v;
            const double depth = 0.06 + 0.1 * v;
            return glm::dvec3(x, y, -4.6 + depth * std::sin(2 * kPi * x / 0.35));
        },
        160, 24, cloth, {6.0f, 4.0f}, [](glm::dvec3) { return glm::dvec3(0, 0, 1); });

    s.lights.push_back(
        {Light::Type::Directional, glm::normalize(glm::vec3(0.45f, -1.0f, -0.3f)), glm::vec3(1.1f, 1.05f, 0.95f)});
    s.lights.push_back({Light::Type::Point, {7.0f, 3.0f, 2.0f}, glm::vec3(6.0f, 5.0f, 3.5f)});
    s.ambient = glm::vec3(0.18f, 0.19f, 0.22f);
    s.views.emplace_back("nave", makeView({-9.5, 1.7, 0.5}, {5.0, 2.5, -0.5}));
    s.views.emplace_back("colonnade", makeView({-6.0, 1.6, -1.2}, {0.0, 3.2, -3.6}));
    s.views.emplace_back("stairs", makeView({3.5, 1.3, 1.8}, {9.0, 1.0, -0.5}));
    s.views.emplace_back("curtain", makeView({-1.6, 1.6, -1.6}, {-3.2, 1.9, -4.6}));
    s.views.emplace_back("gallery", makeView({-9.5, 7.8, 5.2}, {2.0, 3.0, -2.0}));
    return s;
}

}  // namespace ssfx::scene
