// Analytic 3-D scenes for the AO work before (and beside) the Vulkan scene renderer:
// planes, axis-aligned boxes and spheres in camera space (camera at the origin looking
// down -z, metres), rendered to depth buffers by exact ray casting and usable as the
// ray-traced ground truth's geometry (ao::RayScene).
#pragma once

#include <string_view>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"

namespace ssfx::scene {

class AnalyticScene : public ao::RayScene {
public:
    void addPlane(ao::Vec3d point, ao::Vec3d normal);  //!< the half-space behind `normal` is solid
    void addBox(ao::Vec3d lo, ao::Vec3d hi);
    void addSphere(ao::Vec3d centre, double radius);
    ao::RayHit intersect(const ao::Vec3d& origin, const ao::Vec3d& dir, double tMin, double tMax) const override;

private:
    struct Plane {
        ao::Vec3d p, n;
    };
    struct Box {
        ao::Vec3d lo, hi;
    };
    struct Sphere {
        ao::Vec3d c;
        double r;
    };
    std::vector<Plane> planes_;
    std::vector<Box> boxes_;
    std::vector<Sphere> spheres_;
};

//! "corner": a floor y = -1 meeting a back wall z = -5 (an inside corner), sky above 1.5 m
//! on the wall's plane is not modelled: the wall is infinite.
AnalyticScene cornerScene();
//! "room": floor, back and side walls (open above: sky), boxes from 5 cm to 2 m, a stair
//! of boxes, a thin column, spheres on the floor and in the air: AO at many scales.
AnalyticScene roomScene();
//! By name ("corner", "room"); throws ssfx::Error listing the names.
AnalyticScene analyticSceneByName(std::string_view name);

//! Per-pixel primary-ray results through pixel centres: hardware depth (zToDepth of the
//! exact hit, as float32; 1 = sky with an infinite far plane), exact camera-space z and
//! the geometric normal (0 for sky).
struct GeometryBuffer {
    ImageF depth, z;
    std::vector<ao::Vec3d> normals;  //!< row-major
};
GeometryBuffer castGeometry(const ao::RayScene& scene, const Camera& camera, int width, int height,
                            const Exec& exec = {});

}  // namespace ssfx::scene
