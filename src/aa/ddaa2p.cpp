// ddaa2p ("plus"): ddaa2 on a 2x render, then the ssaax2 resolve (DDAA paper section 4:
// recommended where rendering at twice the resolution is affordable; quality close to ssaax4).
#include "src/aa/ppaa_common.hpp"
#include "ssfx/aa/ddaa.hpp"
#include "ssfx/aa/resolve.hpp"

namespace ssfx::aa {

namespace {
void checkInput2x(ImageView<const Rgba8> in2x) {
    detail::checkInput("ddaa2p", in2x);
    if (in2x.width() % 2 != 0 || in2x.height() % 2 != 0)
        throw Error(fmt::format("ddaa2p: input size {}x{} is not divisible by 2 (it takes the 2x render)", in2x.width(),
                                in2x.height()));
}
}  // namespace

ImageRgba8 ddaa2p(ImageView<const Rgba8> in2x, const Ddaa2Params& params, const Exec& exec) {
    checkInput2x(in2x);
    const ImageRgba8 aa = ddaa2(in2x, params, exec);
    return ssaax2(aa.view(), params.filtering, exec, params.texture);
}

void ddaa2p(ImageView<const Rgba8> in2x, ImageView<Rgba8> out, const Ddaa2Params& params, const Exec& exec) {
    checkInput2x(in2x);
    const ImageRgba8 aa = ddaa2(in2x, params, exec);
    ssaax2(aa.view(), out, params.filtering, exec, params.texture);
}

}  // namespace ssfx::aa
