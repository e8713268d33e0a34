#version 450
// The AO sample pass (SAO paper sections 2.3-2.5, eqs. 3-10 and the updated falloff; spec
// sao.md "Passes" 3; the CPU's detail::samplePass in src/ao/ao_sampling.hpp), and AlchemyAO's
// (eq. 1; spec_estimator = 1: level 0 only, no pyramid). One invocation per pixel of the
// region (the quad-aligned work region for SAO, the output region for AlchemyAO): position
// from z (eq. 3), the face normal from quad-pair differences (eq. 4), the screen-space radius
// (eq. 5), the spiral taps (eqs. 6-7) rotated by the per-pixel hash angle (eq. 8), each tap
// read from its pyramid level (eqs. 9-10), the estimator summed in tap order. Raw A, before
// any filtering; sky pixels and pixels whose quad holds sky get 1.
#define SSFX_AO_TABLES_BINDING 2
#include "ao.glsl"

layout(set = 0, binding = 0) uniform sampler2D zLevels;  // level 0 = z, then the pyramid
layout(set = 0, binding = 1, r32f) uniform writeonly image2D aOut;

// z of level m at (x, y), the coordinates clamped to the level (max(1, size >> m)).
float zAt(int m, int x, int y) {
    const ivec2 last = ivec2(max(1, pc.width >> m), max(1, pc.height >> m)) - 1;
    return texelFetch(zLevels, clamp(ivec2(x, y), ivec2(0), last), m).r;
}

// Camera-space position at pixel (x, y)'s centre with depth z: (z fx(x), z fy(y), z), with
// fx(x) = ax + bx x (the CPU's PositionTables, the same floats).
vec3 positionAt(int x, int y, float z) {
    precise float fx = pc.ax + pc.bx * float(x);
    precise float fy = pc.ay + pc.by * float(y);
    precise vec3 c = vec3(z * fx, z * fy, z);
    return c;
}

// The two pixels of v's 2x2-quad pair along an axis of n pixels (clamped for an odd n).
ivec2 quadPair(int v, int n) {
    int a = v & ~1, b = a + 1;
    if (b >= n) a = n - 2, b = n - 1;
    return ivec2(a, b);
}

// 1 / 2 pi's first 128 bits after the binary point, most significant word first:
// 0.28be60db 9391054a 7f09d5f4 7d4d3770... (hex).
const uint kInvTwoPi[4] = uint[4](0x28be60dbu, 0x9391054au, 0x7f09d5f4u, 0x7d4d3770u);
// The 32 bits of 1 / 2 pi's fraction that start at bit k (0: the first after the point).
uint invTwoPiBits(int k) {
    const int i = k >> 5, s = k & 31;
    return s == 0 ? kInvTwoPi[i] : (kInvTwoPi[i] << uint(s)) | (kInvTwoPi[i + 1] >> uint(32 - s));
}

// The angle a (>= 0, a float) reduced to [-pi, pi], as the CPU's vector kernel does in
// double (a - 2 pi round(a / 2 pi)): GLSL's sine and cosine are only specified on
// [-pi, pi], and the hash angles reach 10^8 rad. a = n + f with n = floor(a) = M 2^e (M an
// integer below 2^32, e = 0 while n < 2^32) and f = a - n in [0, 1), both exact. n / 2 pi's
// fraction of a turn is that of M times the 64 bits of 1 / 2 pi's fraction from bit e on
// (two 32 x 32 -> 64-bit products, wrapping): its top 32 bits, read as signed, are the angle
// in [-1/2, 1/2) turn within 2^-32 turn, so the reduction adds about an ulp of pi.
float reduceAngle(float a) {
    const float n = floor(a);
    int e = 0;
    if (n >= 4294967296.0) {
        int ex;
        frexp(n, ex);  // n = f 2^ex, f in [0.5, 1)
        e = min(ex - 24, 63);  // n / 2^e < 2^24, an integer (angles here stay below 2^36:
    }                          // 10 times an int, plus a spiral angle)
    const uint m = uint(ldexp(n, -e));
    uint hiMsb, hiLsb, loMsb, loLsb;
    umulExtended(m, invTwoPiBits(e), hiMsb, hiLsb);
    umulExtended(m, invTwoPiBits(e + 32), loMsb, loLsb);
    const int turns = int(hiLsb + loMsb);
    precise float r = float(turns) * 1.4629180792671596e-09;  // 2 pi / 2^32
    precise float s = r + (a - n);
    precise float wrapped = s > 3.14159265 ? s - 6.28318531 : s;
    return wrapped;
}

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    const int x = pc.regionX + p.x, y = pc.regionY + p.y;
    const int w = pc.width, h = pc.height;
    const float zc = zAt(0, x, y);
    float result = 1.0;
    if (!isinf(zc) && w >= 2 && h >= 2) {
        // The face normal (eq. 4): n = normalize(dC/dy x dC/dx) from the quad pairs.
        const ivec2 px = quadPair(x, w), py = quadPair(y, h);
        precise vec3 ddx = positionAt(px.y, y, zAt(0, px.y, y)) - positionAt(px.x, y, zAt(0, px.x, y));
        precise vec3 ddy = positionAt(x, py.y, zAt(0, x, py.y)) - positionAt(x, py.x, zAt(0, x, py.x));
        precise vec3 n = vec3(ddy.y * ddx.z - ddy.z * ddx.y, ddy.z * ddx.x - ddy.x * ddx.z,
                              ddy.x * ddx.y - ddy.y * ddx.x);
        precise float nn = (n.x * n.x + n.y * n.y) + n.z * n.z;
        const float len = crSqrt(nn);
        if (len > 0.0 && !isinf(len)) {
            const float inv = crDiv(1.0, len);
            precise vec3 nu = n * inv;
            const vec3 c = positionAt(x, y, zc);
            const float ssRadius = crDiv(pc.radiusS, zc);  // eq. 5
            // Eq. 8 as released: phi = 10 float((3 x) ^ (y + x y)).
            precise float phi = 10.0 * float((3 * x) ^ (y + x * y));
            const float pr = reduceAngle(phi);
            const float cphi = cos(pr), sphi = sin(pr);
            precise float sum = 0.0;
            for (int k = 0; k < tables.numSamples; ++k) {
                precise float hk = ssRadius * tables.alpha[k];
                float ux, uy;
                if (spec_spinInFloat != 0) {  // the released tapLocation(): the angle summed in float
                    precise float angle = tables.tapAngle[k] + phi;
                    const float ar = reduceAngle(angle);
                    ux = cos(ar), uy = sin(ar);
                } else {  // the spiral's direction rotated by phi
                    precise float rx = tables.dirX[k] * cphi - tables.dirY[k] * sphi;
                    precise float ry = tables.dirX[k] * sphi + tables.dirY[k] * cphi;
                    ux = rx, uy = ry;
                }
                precise float ox = hk * ux, oy = hk * uy;
                const int sx = x + int(ox), sy = y + int(oy);  // truncation toward zero
                // Eqs. 9-10: m = clamp(findMSB(int(h)) - log2 q', 0, MAX_MIP) (0 from 2^31,
                // where the CPU's int(h) overflows to INT_MIN).
                const int m = hk < 2147483648.0 ? clamp(findMSB(int(hk)) - tables.logQ, 0, pc.levels) : 0;
                const float zq = zAt(m, sx >> m, sy >> m);
                if (isinf(zq)) continue;  // sky occludes nothing
                precise vec3 v = positionAt(sx, sy, zq) - c;
                precise float vv = (v.x * v.x + v.y * v.y) + v.z * v.z;
                precise float vn = (v.x * nu.x + v.y * nu.y) + v.z * nu.z;
                if (spec_estimator == 0) {  // SAO's updated falloff
                    precise float f = max(tables.r2 - vv, 0.0);
                    const float q = crDiv(vn - tables.bias, vv + tables.epsilon);
                    precise float term = ((f * f) * f) * (q > 0.0 ? q : 0.0);
                    sum += term;
                } else {  // AlchemyAO, eq. 1
                    precise float num = vn + zc * tables.bias;
                    sum += crDiv(num > 0.0 ? num : 0.0, vv + tables.epsilon);
                }
            }
            precise float a = 1.0 - (sum * tables.scale) * tables.scale2;
            result = a > 0.0 ? a : 0.0;
            if (tables.exponent == 0.0)
                result = 1.0;  // a^0 (pow(0, 0) is undefined in GLSL)
            else if (tables.exponent != 1.0)
                result = pow(result, tables.exponent);
        }
    }
    imageStore(aOut, p, vec4(result));
}
