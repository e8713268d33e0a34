// Per-pixel pieces of DDAA shared by ddaa1 and ddaa2 (Klein, DDAA; spec ppaa.md).
#pragma once

#include <algorithm>
#include <cmath>

#include "src/aa/luma_planes.hpp"
#include "src/aa/ppaa_common.hpp"
#include "ssfx/aa/ddaa.hpp"

namespace ssfx::aa::detail {

//! True when every read of ddaa2's edge search on an image of this size equals a pair-plane
//! value (then the vector kernel runs; otherwise the scalar one). In ddaa2.cpp.
bool searchReadsArePairReads(const Texture& tex, int rounds);

//! Diffusion direction (unit edge vector) and strength, after the small-structure rule.
struct Diffusion {
    float dirX, dirY;
    float strength;
};

inline Diffusion diffusion(const Luma3x3& n, const EdgeSides& s, const Ddaa1Params& p) {
    // Scharr kernel (Jaehne et al. 1999; paper section 2.1): the most rotation-invariant
    // 3x3 derivative, so the diffusion is equally strong at every angle.
    const float k1 = 162.0f / 256.0f, k2 = 47.0f / 256.0f;
    const float Dx = (n.W * k1 + n.SW * k2 + n.NW * k2) - (n.E * k1 + n.SE * k2 + n.NE * k2);
    const float Dy = (n.S * k1 + n.SW * k2 + n.SE * k2) - (n.N * k1 + n.NW * k2 + n.NE * k2);
    const float ex = -Dy, ey = Dx;  // along the edge, perpendicular to the gradient
    const float len = std::sqrt(ex * ex + ey * ey);
    const float raw = p.strength * std::sqrt(len);
    Diffusion d{0.0f, 0.0f, 0.0f};
    if (!(raw < 1e-6f)) {
        d.strength = minf(1.0f, raw);
        d.dirX = ex / len;
        d.dirY = ey / len;
    }
    // Ridge or valley (both neighbours across the edge on the same side of C, e.g. a thin
    // line): diffuse less the steeper it is (section 2.2; AXAA only handled ridges).
    if ((s.g1 > 0.0f) == (s.g2 > 0.0f))
        d.strength *= 1.0f - minf(1.0f, p.ridgeFactor * minf(std::fabs(s.g1), std::fabs(s.g2)));
    return d;
}

//! Average of two bilinear reads at centre -/+ step (+ offset), step = dir * maxDiffusion *
//! strength pixels; (offU, offV) is the edge-search offset in texture units.
inline Rgb diffuse(const Texture& tex, int x, int y, const Diffusion& d, float maxDiffusion, float offU, float offV) {
    const float sx = d.dirX * maxDiffusion * d.strength;
    const float sy = d.dirY * maxDiffusion * d.strength;
    const float u = tex.centreU(x), v = tex.centreV(y);
    const float du = sx * tex.invW(), dv = sy * tex.invH();
    const Rgb a = tex.sample(u - du + offU, v - dv + offV);
    const Rgb b = tex.sample(u + du + offU, v + dv + offV);
    return {(a.r + b.r) * 0.5f, (a.g + b.g) * 0.5f, (a.b + b.b) * 0.5f};
}

}  // namespace ssfx::aa::detail
