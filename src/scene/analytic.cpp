// Analytic scenes for the AO work (see scene/analytic.hpp).
#include "ssfx/scene/analytic.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ssfx/core/error.hpp"

namespace ssfx::scene {

using ao::RayHit;
using ao::Vec3d;

namespace {
double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3d normalize(Vec3d v) {
    const double l = std::sqrt(dot(v, v));
    return {v.x / l, v.y / l, v.z / l};
}
}  // namespace

void AnalyticScene::addPlane(Vec3d point, Vec3d normal) { planes_.push_back({point, normalize(normal)}); }
void AnalyticScene::addBox(Vec3d lo, Vec3d hi) { boxes_.push_back({lo, hi}); }
void AnalyticScene::addSphere(Vec3d c, double r) { spheres_.push_back({c, r}); }

RayHit AnalyticScene::intersect(const Vec3d& o, const Vec3d& d, double tMin, double tMax) const {
    RayHit best{INFINITY, {0, 0, 0}};
    auto take = [&](double t, Vec3d n) {
        if (t > tMin && t < tMax && t < best.t) {
            if (dot(n, d) > 0) n = {-n.x, -n.y, -n.z};  // face the ray
            best = {t, n};
        }
    };
    for (const Plane& p : planes_) {
        const double den = dot(p.n, d);
        if (den != 0) take(dot(p.n, {p.p.x - o.x, p.p.y - o.y, p.p.z - o.z}) / den, p.n);
    }
    for (const Box& b : boxes_) {
        // Slabs: the entry point's axis gives the normal.
        double t0 = -INFINITY, t1 = INFINITY;
        int axis = -1;
        const double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
        const double oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
        bool miss = false;
        for (int a = 0; a < 3 && !miss; ++a) {
            if (dd[a] == 0) {
                miss = oo[a] < lo[a] || oo[a] > hi[a];
                continue;
            }
            double ta = (lo[a] - oo[a]) / dd[a], tb = (hi[a] - oo[a]) / dd[a];
            if (ta > tb) std::swap(ta, tb);
            if (ta > t0) t0 = ta, axis = a;
            t1 = std::min(t1, tb);
        }
        if (miss || t0 > t1 || axis < 0) continue;
        Vec3d n{0, 0, 0};
        (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = 1;
        take(t0, n);
    }
    for (const Sphere& s : spheres_) {
        const Vec3d oc{o.x - s.c.x, o.y - s.c.y, o.z - s.c.z};
        const double b = dot(oc, d), c = dot(oc, oc) - s.r * s.r, disc = b * b - c;
        if (disc < 0) continue;
        const double t = -b - std::sqrt(disc);
        const Vec3d p{o.x + d.x * t, o.y + d.y * t, o.z + d.z * t};
        take(t, normalize({p.x - s.c.x, p.y - s.c.y, p.z - s.c.z}));
    }
    return best;
}

AnalyticScene cornerScene() {
    AnalyticScene s;
    s.addPlane({0, -1, 0}, {0, 1, 0});
    s.addPlane({0, 0, -5}, {0, 0, 1});
    return s;
}

AnalyticScene roomScene() {
    AnalyticScene s;
    s.addPlane({0, -1.5, 0}, {0, 1, 0});    // floor
    s.addPlane({0, 0, -14}, {0, 0, 1});     // back wall
    s.addBox({-9, -1.5, -14}, {-5, 6, 0});  // side walls (thick boxes, open above: sky)
    s.addBox({5, -1.5, -14}, {9, 6, 0});
    // Boxes from 5 cm to 2 m along the floor and against the back wall.
    const double sizes[] = {0.05, 0.15, 0.4, 0.8, 1.2, 2.0};
    double x = -4.6;
    for (double sz : sizes) {
        s.addBox({x, -1.5, -10.5 - sz / 2}, {x + sz, -1.5 + sz, -10.5 + sz / 2});
        x += sz + 0.5;
    }
    // A stair against the back wall on the right, a thin column, spheres.
    for (int k = 0; k < 5; ++k) s.addBox({1.5 + 0.5 * k, -1.5, -14}, {4.8, -1.5 + 0.25 * (k + 1), -12.5});
    s.addBox({-0.05, -1.5, -7.05}, {0.05, 6, -6.95});
    s.addSphere({-2.5, -0.9, -6.5}, 0.6);
    s.addSphere({2.2, 0.8, -8.0}, 0.5);
    s.addSphere({3.0, -1.3, -5.5}, 0.2);
    return s;
}

AnalyticScene analyticSceneByName(std::string_view name) {
    if (name == "corner") return cornerScene();
    if (name == "room") return roomScene();
    throw Error(fmt::format("unknown analytic scene '{}' (known: corner, room)", name));
}

GeometryBuffer castGeometry(const ao::RayScene& scene, const Camera& camera, int width, int height, const Exec& exec) {
    const Projection proj = ssfx::projection(camera, width, height);
    GeometryBuffer g{ImageF(width, height), ImageF(width, height),
                     std::vector<Vec3d>(std::size_t(width) * std::size_t(height), Vec3d{0, 0, 0})};
    parallelRows(height, exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < width; ++x) {
                const Vec3d dir = ao::primaryRay(proj, float(x) + 0.5f, float(y) + 0.5f);
                const RayHit h = scene.intersect({0, 0, 0}, dir, 0.0, INFINITY);
                const double z = -h.t * -dir.z;  // camera-space z of the hit (dir.z < 0)
                const bool hit = std::isfinite(h.t) && (std::isinf(camera.zFar) || z > camera.zFar) && z < camera.zNear;
                g.z(x, y) = hit ? float(z) : -INFINITY;
                g.depth(x, y) = hit ? float(ao::zToDepth(z, camera)) : 1.0f;
                if (hit) g.normals[std::size_t(y) * std::size_t(width) + std::size_t(x)] = h.normal;
            }
    });
    return g;
}

}  // namespace ssfx::scene
