// The AO family's registry: sao, alchemy, gtao, raytraced (MethodDesc plus how each is run). The
// CLI, the evaluation and the property tests pick the method, its parameters and presets
// here; nothing outside names the methods' functions by string.
#pragma once

#include <span>
#include <string_view>
#include <variant>

#include "ssfx/ao/alchemy.hpp"
#include "ssfx/ao/gtao.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/method.hpp"
#include "ssfx/core/progress.hpp"

namespace ssfx::ao {

//! One method's parameters: the struct its table describes.
using AoParams = std::variant<SaoParams, AlchemyParams, GtaoParams, RaytracedParams>;

//! What a method reads: the depth buffer (guard band included) and the camera of the whole
//! buffer; `geometry` for the ray-traced truth, which reads the scene, not the depth (only
//! the depth's size is used then).
struct AoInput {
    ImageView<const float> depth;
    Camera camera;
    const RayScene* geometry = nullptr;
    ProgressFn progress;  //!< reported by the slow methods (raytraced: rows done)
    //! Camera-space normals of the whole buffer (a G-buffer's), for the methods that take them
    //! (AoMethodInfo::takesNormals); empty: from depth.
    ImageView<const Vec3> normals;
};

struct AoMethodInfo : MethodDesc {
    bool needsGeometry;  //!< raytraced: AoInput::geometry is required
    bool takesNormals;   //!< gtao: AoInput::normals is used when given
    //! The parameters of `preset` ("" = the defaults); throws ssfx::Error naming the presets.
    AoParams (*defaults)(std::string_view preset);
    //! Throws ssfx::Error for a parameter outside its table's range or a rule across fields.
    void (*validate)(const AoParams& params);
    //! Ambient visibility of the inner region (the depth's size less twice the guard band).
    ImageF (*run)(const AoInput& input, const AoParams& params, const Exec& exec);
};

std::span<const AoMethodInfo> aoMethods();
//! Throws ssfx::Error listing the ids for an unknown one.
const AoMethodInfo& aoMethodById(std::string_view id);

//! Sets a parameter of `params` (the method's struct) by name, checked by the method's table.
void setParam(const AoMethodInfo& method, AoParams& params, std::string_view name, double value);
//! Every AO method has a guard band: the pixels on each side of the depth buffer not output.
int guardBandOf(const AoParams& params);

}  // namespace ssfx::ao
