#version 450
// GTAO pass 2b: the main pass over the work region (spec gtao.md section 5; the CPU's
// GtaoMain::pixel in src/ao/gtao_pixel.hpp, step for step): per pixel the view vector from the
// pulled position, the normal (from pass 2a), the radius in pixels, then per slice its
// direction from the Hilbert/R2 noise, the projected normal's angle gamma, and per step two
// samples (either side) point-sampled from the chain level the step's distance picks, each
// raising its side's horizon cosine with the falloff weight; the slice's visibility from the
// two horizons. A before the denoiser (may exceed 1), sky 1. The cosines, sines, arc cosines,
// log2 and pow are the device's, and so are division and square root (not corrected by crDiv
// and crSqrt as in the other passes: this pass is held to a bound, not to the CPU's bits, and
// the corrections took 45 % of its time on lavapipe); the rest is the CPU's float operations
// in its order (precise).
#define SSFX_GTAO_TABLES_BINDING 3
#include "gtao.glsl"

layout(set = 0, binding = 0) uniform sampler2D chain;  // z, level m the chain's level m
layout(set = 0, binding = 1, rgba32f) uniform readonly image2D normals;  // work region
layout(set = 0, binding = 2, r32f) uniform writeonly image2D aOut;       // work region

const float kPi = 3.14159265358979323846;
const float kHalfPi = kPi / 2.0;

float gtaoAcos(float x) {
    if (gt.fastAcos == 0) return acos(x);
    const float ax = abs(x);
    precise float oneMinus = 1.0 - ax;
    const float root = intBitsToFloat(0x1FBD1DF5 + (floatBitsToInt(oneMinus) >> 1));
    precise float r = (kHalfPi - 0.156583 * ax) * root;
    precise float other = kPi - r;
    return x >= 0.0 ? r : other;
}
// unitOrZero with the device's square root and division (gtao.glsl's gtaoUnitOrZero, which
// the normals pass uses, corrects them to the CPU's bits).
vec3 unitOrZeroDevice(vec3 n) {
    const float len = sqrt(gtaoDot(n, n));
    if (!(len > 0.0) || isinf(len) || isnan(len)) return vec3(0.0);
    return vec3(n.x / len, n.y / len, n.z / len);
}
// GLSL's cos is specified on [-pi, pi]: 2 h - gamma reaches 2.5 pi.
float cosReduced(float a) {
    precise float r = a > kPi ? a - 2.0 * kPi : a < -kPi ? a + 2.0 * kPi : a;
    return cos(r);
}

// floor((2 p + 1) wm / (2 n)) for p in [0, n) without an integer division (which a CPU device
// such as lavapipe runs lane by lane): a float estimate, within one of it whatever the
// device's rounding (relative error about 1e-7 on a quotient below 2^15), then one
// correction by the integer remainder. The same integers as the division.
int texelOf(int p, int wm, int n) {
    const int num = (2 * p + 1) * wm, den = 2 * n;
    int q = int(floor(float(num) * (1.0 / float(den))));
    const int r = num - q * den;
    q -= r < 0 ? 1 : 0;
    q += r >= den ? 1 : 0;
    return q;
}

// t of chain level m at buffer pixel (px, py): point sampling at the full-resolution centre,
// floor((p + 0.5) W_m / W) with p clamped into the buffer.
float chainT(int m, int px, int py) {
    const ivec2 size = ivec2(pc.width, pc.height);
    const ivec2 sm = max(ivec2(1), size >> m);
    const ivec2 q = clamp(ivec2(px, py), ivec2(0), size - 1);
    const ivec2 texel = ivec2(texelOf(q.x, sm.x, size.x), texelOf(q.y, sm.y, size.y));
    return -texelFetch(chain, texel, m).r;
}

// One step's sample on one side: the horizon cosine h moves up to the sample's.
void gtaoSample(int px, int py, int m, vec3 c, vec3 v, float start, inout float h) {
    const bool inside = px >= 0 && py >= 0 && px < pc.width && py < pc.height;
    if (!inside && gt.offscreenDiscard != 0) return;
    const float ts = chainT(m, px, py);
    if (isinf(ts)) return;  // sky: weight 0
    precise vec3 dv = gtaoPosition(px, py, -ts) - c;
    const float len = sqrt(gtaoDot(dv, dv));
    const float cs = gtaoDot(dv, v) / len;
    float lenW = len;
    if (gt.toc1 != 1.0) {
        precise float tz = gt.toc1 * dv.z;
        precise float s = (dv.x * dv.x + dv.y * dv.y) + tz * tz;
        lenW = sqrt(s);
    }
    precise float num = gt.re - lenW;
    const float w = clamp(num / gt.fRe, 0.0, 1.0);
    precise float cw = start + w * (cs - start);
    if (gt.thickness > 0.0 && cw < h) {
        precise float hh = h + gt.thickness * (cw - h);  // the paper's thickness heuristic
        h = hh;
    } else {
        h = max(h, cw);
    }
}

float pixelA(int x, int y) {
    const float t0 = chainT(0, x, y);
    if (isinf(t0)) return 1.0;  // sky: unoccluded
    precise float t = t0 * 0.99999;
    const vec3 c = gtaoPosition(x, y, -t);
    const float invLen = 1.0 / sqrt(gtaoDot(c, c));
    precise vec3 v = -c * invLen;
    vec3 n = imageLoad(normals, ivec2(x - pc.regionX, y - pc.regionY)).xyz;
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) n = v;
    const float r = pc.radiusS / t;  // rNum / t
    precise float fade = (10.0 - r) / 100.0;
    const float v0 = gt.nearFade != 0 ? 0.5 * clamp(fade, 0.0, 1.0) : 0.0;
    const float smin = 1.3 / r;
    const int ni = 2 * (((y - gt.guard) & 63) * 64 + ((x - gt.guard) & 63));
    const vec2 noise = vec2(gt.noise[ni], gt.noise[ni + 1]);
    precise float sum = 0.0;
    for (int k = 0; k < gt.slices; ++k) {
        precise float phi = (float(k) + noise.x) / float(gt.slices) * kPi;
        const float cphi = cos(phi), sphi = sin(phi);
        const vec3 d = vec3(cphi, sphi, 0.0);
        precise float ox = cphi * r, oy = -sphi * r;  // screen y is down
        const float dv = gtaoDot(d, v);
        precise vec3 dp = d - dv * v;
        const vec3 axis = unitOrZeroDevice(gtaoCross(dp, v));
        const float na = gtaoDot(n, axis);
        precise vec3 np = n - na * axis;
        const float l = sqrt(gtaoDot(np, np));
        float cg = 1.0, gamma = 0.0;
        if (l > 0.0) {
            cg = clamp(gtaoDot(np, v) / l, 0.0, 1.0);
            const float side = gtaoDot(dp, np);
            const float a = gtaoAcos(cg);
            gamma = side > 0.0 ? a : side < 0.0 ? -a : 0.0;
        }
        const float sg = sin(gamma);
        precise float gp = gamma + kHalfPi, gn = gamma - kHalfPi;
        const float lowPos = cos(gp), lowNeg = cos(gn);
        const float startPos = gt.minusOne != 0 ? -1.0 : lowPos, startNeg = gt.minusOne != 0 ? -1.0 : lowNeg;
        float hp = startPos, hn = startNeg;
        for (int j = 0; j < gt.steps; ++j) {
            precise float base = float(k + j * gt.steps) * 0.6180339887498948;
            precise float xjRaw = noise.y + base;
            precise float xj = xjRaw - floor(xjRaw);
            precise float s = (float(j) + xj) / float(gt.steps);
            precise float sp = s * s;
            const float spacing = gt.spacingPower == 2.0 ? sp : pow(s, gt.spacingPower);
            precise float u = spacing + smin;
            precise float sx = u * ox, sy = u * oy;
            precise float len2 = sx * sx + sy * sy;
            precise float lodRaw = log2(sqrt(len2)) - gt.mipOffset;
            const float lod = clamp(lodRaw, 0.0, 5.0);
            precise float lodHalf = lod + 0.5;
            const int m = min(4, int(floor(lodHalf)));
            const int qx = int(roundEven(sx)), qy = int(roundEven(sy));
            gtaoSample(x + qx, y + qy, m, c, v, startPos, hp);
            gtaoSample(x - qx, y - qy, m, c, v, startNeg, hn);
        }
        if (gt.minusOne != 0) hp = max(hp, lowPos), hn = max(hn, lowNeg);  // onto the hemisphere
        const float h1 = gtaoAcos(hp), h0 = -gtaoAcos(hn);
        precise float lp = gt.lift != 0 ? 0.95 * l + 0.05 : l;
        precise float twoH0 = 2.0 * h0 - gamma, twoH1 = 2.0 * h1 - gamma;
        precise float i0 = ((cg + 2.0 * h0 * sg) - cosReduced(twoH0)) * 0.25;
        precise float i1 = ((cg + 2.0 * h1 * sg) - cosReduced(twoH1)) * 0.25;
        sum += lp * (i0 + i1);
    }
    precise float mean = (v0 + sum) / float(gt.slices);
    const float a = max(0.0, mean);
    return max(0.03, gt.finalPower == 1.0 ? a : pow(a, gt.finalPower));
}

void main() {
    ivec2 p;
    if (!regionPixel(p)) return;
    float a = pixelA(pc.regionX + p.x, pc.regionY + p.y);
    if (gt.xegtaoStorage != 0) a = gtaoStore(a);
    imageStore(aOut, p, vec4(a));
}
