#version 450
// The 2x2 quad bilateral (end of SAO paper section 2.3; the CPU's ao::quadBilateral): within
// each 2x2 quad of the buffer grid, where |dz| < quadThreshold, A is averaged over the pair
// in x, then in y on the result; pairs with a partner outside the region are left alone. One
// invocation per quad of the (quad-aligned) work region, from the raw A to a new image. With
// packBlurInput it also stores what the blur reads (spec_packing: 1 packBlurInput's 16-bit
// key, 2 the released RGB8 storage): A in 8 bits and the key's z in a buffer-sized image.
#define SSFX_AO_TABLES_BINDING 4
#include "ao.glsl"

layout(set = 0, binding = 0, r32f) uniform readonly image2D aRaw;     // the region
layout(set = 0, binding = 1, r32f) uniform writeonly image2D aQuad;   // the region
layout(set = 0, binding = 2, r32f) uniform readonly image2D zBuffer;  // level 0, buffer pixels
layout(set = 0, binding = 3, r32f) uniform writeonly image2D zKey;    // packing: the blur's z

bool near(float za, float zb) { return abs(za - zb) < tables.quadThreshold; }  // false for sky (NaN, inf)

// ssfx::ao::packZ: the z the blur sees after packBlurInput's 16-bit key round trip.
float packZ(float z) {
    if (isinf(z)) return z;  // sky is told apart by the depth test, not by the key
    const float key = clamp(crDiv(z, tables.packZMin), 0.0, 1.0);
    precise float k256 = key * 256.0;
    const float t = min(floor(k256), 255.0);
    precise float hiScaled = t * (1.0 / 256.0) * 255.0;
    const float hi = crDiv(roundEven(hiScaled), 255.0);
    precise float loScaled = (k256 - t) * 255.0;
    const float lo = crDiv(roundEven(loScaled), 255.0);
    precise float hi256 = hi * 256.0;
    precise float k = roundEven(hi256) * (1.0 / 256.0) + lo * (1.0 / 256.0);
    precise float r = k * tables.packZMin;
    return r;
}

// ssfx::ao::releasedKey: the key the released blur reads back (RGB8: the key in G and B).
float releasedKey(float z) {
    if (isinf(z)) return z;
    precise float scaled = z * crDiv(1.0, tables.packZMin);
    const float key = clamp(scaled, 0.0, 1.0);
    precise float k256 = key * 256.0;
    const float t = floor(k256);
    precise float gScaled = t * (1.0 / 256.0) * 255.0;
    const float g = crDiv(roundEven(gScaled), 255.0);
    precise float bScaled = (k256 - t) * 255.0;
    const float b = crDiv(roundEven(bScaled), 255.0);
    precise float r = g * crDiv(256.0, 257.0) + b * crDiv(1.0, 257.0);
    return r;
}

void main() {
    // Quad q covers region pixels (2 q.x + i, 2 q.y + j); the region starts on even pixels.
    const ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 r0 = 2 * q;
    if (r0.x >= pc.regionW || r0.y >= pc.regionH) return;
    const bool hasX = r0.x + 1 < pc.regionW, hasY = r0.y + 1 < pc.regionH;
    const ivec2 b0 = ivec2(pc.regionX, pc.regionY) + r0;  // buffer pixel of the quad's corner
    float a[4], z[4];  // (0, 0), (1, 0), (0, 1), (1, 1)
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        const bool inside = (o.x == 0 || hasX) && (o.y == 0 || hasY);
        a[k] = inside ? imageLoad(aRaw, r0 + o).r : 0.0;
        z[k] = inside ? imageLoad(zBuffer, b0 + o).r : 0.0;
    }
    if (hasX) {
        for (int j = 0; j < (hasY ? 2 : 1); ++j)
            if (near(z[2 * j], z[2 * j + 1])) {
                precise float m = (a[2 * j] + a[2 * j + 1]) * 0.5;
                a[2 * j] = m, a[2 * j + 1] = m;
            }
    }
    if (hasY) {
        for (int i = 0; i < (hasX ? 2 : 1); ++i)
            if (near(z[i], z[i + 2])) {
                precise float m = (a[i] + a[i + 2]) * 0.5;
                a[i] = m, a[i + 2] = m;
            }
    }
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        if ((o.x == 1 && !hasX) || (o.y == 1 && !hasY)) continue;
        float v = a[k];
        if (spec_packing != 0) {
            v = packAo(v);
            imageStore(zKey, b0 + o, vec4(spec_packing == 2 ? releasedKey(z[k]) : packZ(z[k])));
        }
        imageStore(aQuad, r0 + o, vec4(v));
    }
}
