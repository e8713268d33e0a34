// Embree 3 triangle scenes for the ray-traced AO ground truth (see raytrace.hpp).
#include "ssfx/scene/raytrace.hpp"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <cmath>

#include "ssfx/core/error.hpp"

namespace ssfx::scene {

namespace {

class EmbreeScene final : public ao::RayScene {
public:
    EmbreeScene(const Scene& scene, const CameraSetup& camera) {
        scene.validate();
        device_ = rtcNewDevice("threads=1");  // building is single-threaded: deterministic and small
        if (!device_)
            throw Error(fmt::format("Embree: cannot create a device (error {})", int(rtcGetDeviceError(nullptr))));
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), scene.vertices.size()));
        for (std::size_t i = 0; i < scene.vertices.size(); ++i) {
            const glm::dvec4 p = camera.view * glm::dvec4(glm::dvec3(scene.vertices[i].position), 1.0);
            v[3 * i] = float(p.x);
            v[3 * i + 1] = float(p.y);
            v[3 * i + 2] = float(p.z);
        }
        auto* idx = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), scene.triangleCount()));
        std::copy(scene.indices.begin(), scene.indices.end(), idx);
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene_, geom);
        rtcReleaseGeometry(geom);
        rtcCommitScene(scene_);
        if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
            throw Error(fmt::format("Embree: building the BVH of '{}' failed (error {})", scene.name,
                                    int(rtcGetDeviceError(device_))));
    }
    ~EmbreeScene() override {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    ao::RayHit intersect(const ao::Vec3d& o, const ao::Vec3d& d, double tMin, double tMax) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = float(o.x);
        rh.ray.org_y = float(o.y);
        rh.ray.org_z = float(o.z);
        rh.ray.dir_x = float(d.x);
        rh.ray.dir_y = float(d.y);
        rh.ray.dir_z = float(d.z);
        rh.ray.tnear = float(tMin);
        rh.ray.tfar = std::isinf(tMax) ? INFINITY : float(tMax);
        rh.ray.mask = 0xFFFFFFFFu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {INFINITY, {0, 0, 0}};
        ao::Vec3d n{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
        const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (!(len > 0.0)) return {INFINITY, {0, 0, 0}};  // degenerate triangle: no surface
        const double s = (n.x * d.x + n.y * d.y + n.z * d.z) > 0.0 ? -1.0 / len : 1.0 / len;  // towards the origin
        return {double(rh.ray.tfar), {n.x * s, n.y * s, n.z * s}};
    }

    // float32 triangles: intersections carry ~1e-7 relative rounding of coordinates up to
    // tens of metres; 0.1 mm per metre clears it and is far below any AO radius.
    double surfaceOffset() const override { return 1e-4; }

private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
};

}  // namespace

std::unique_ptr<ao::RayScene> cameraSpaceRayScene(const Scene& scene, const CameraSetup& camera) {
    return std::make_unique<EmbreeScene>(scene, camera);
}

}  // namespace ssfx::scene
