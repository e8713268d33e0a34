// The G-buffer's file format (gbuffer.hpp).
#include "ssfx/scene/gbuffer.hpp"

#include "ssfx/io/exr.hpp"

namespace ssfx::scene {

void writeGBufferExr(const std::string& path, const GBuffer& g) {
    const int w = g.sampleWidth(), h = g.sampleHeight();
    std::vector<ImageF> planes(12, ImageF(w, h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = g.index(x, y);
            for (int c = 0; c < 3; ++c) planes[std::size_t(c)](x, y) = g.normal[i][c];
            planes[3](x, y) = g.uv[i].x;
            planes[4](x, y) = g.uv[i].y;
            for (int c = 0; c < 4; ++c) planes[std::size_t(5 + c)](x, y) = g.uvGrad[i][c];
            planes[9](x, y) = g.material[i] == GBuffer::kNoMaterial ? -1.0f : float(g.material[i]);
            planes[10](x, y) = float(g.layer[i]);
        }
    planes[11] = g.depth;
    const char* names[] = {"N.X",     "N.Y",     "N.Z",     "UV.U",     "UV.V",  "dUVdx.U",
                           "dUVdx.V", "dUVdy.U", "dUVdy.V", "material", "layer", "Z"};
    std::vector<io::ExrChannel> channels;
    for (std::size_t i = 0; i < planes.size(); ++i) channels.push_back({names[i], planes[i].view()});
    io::writeExr(path, channels);
}

}  // namespace ssfx::scene
