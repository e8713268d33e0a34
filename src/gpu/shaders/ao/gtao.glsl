// Shared by GTAO's passes (spec gtao.md; the CPU's src/ao/gtao_pixel.hpp and gtao.cpp): the
// tables, positions, t = -z reads and the float helpers. As in ao.glsl: every float
// computation is `precise` (no fused multiply-add, the written order), division and square
// root correctly rounded (crDiv, crSqrt), so the chain, the edges, the normals and the
// denoiser give the CPU's float bits from the same inputs. What stays the device's own is
// the main pass's cos, sin, acos, log2 and pow (Vulkan leaves their precision to the
// implementation): its parity with the CPU is a stated bound (tests/gpu/test_gpu_ao.cpp).
#include "ao.glsl"
#include "gtao_constants.h"

layout(set = 0, binding = SSFX_GTAO_TABLES_BINDING, std430) readonly buffer GtaoTablesBlock {
    SSFX_GTAO_TABLES_BLOCK
} gt;

// Camera-space position at pixel (x, y)'s centre with depth z (PositionTables::at).
vec3 gtaoPosition(int x, int y, float z) {
    precise float fx = pc.ax + pc.bx * float(x);
    precise float fy = pc.ay + pc.by * float(y);
    precise vec3 c = vec3(z * fx, z * fy, z);
    return c;
}

float gtaoDot(vec3 a, vec3 b) {
    precise float d = (a.x * b.x + a.y * b.y) + a.z * b.z;
    return d;
}
vec3 gtaoCross(vec3 a, vec3 b) {
    precise vec3 c = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    return c;
}
// The unit vector of n, or (0, 0, 0) where it has none (unitOrZero).
vec3 gtaoUnitOrZero(vec3 n) {
    const float len = crSqrt(gtaoDot(n, n));
    if (!(len > 0.0) || isinf(len) || isnan(len)) return vec3(0.0);
    return vec3(crDiv(n.x, len), crDiv(n.y, len), crDiv(n.z, len));
}

// xegtaoStorage: A / 1.5 as UNORM8 and back (the CPU's xegtaoStore).
float gtaoStore(float a) {
    precise float scaled = clamp(crDiv(a, 1.5), 0.0, 1.0) * 255.0;
    precise float back = crDiv(roundEven(scaled), 255.0) * 1.5;
    return back;
}
