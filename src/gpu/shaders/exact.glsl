// Exact float helpers of the model sampling mode (ppaa.glsl's header says why): Dekker's
// exact product, correctly rounded division and square root from the device's, and the
// exact float-to-8-bit conversion. Self-contained (no bindings): tests/gpu/shaders/exact.comp
// checks them against the CPU's IEEE results.

// a * b == p + e exactly (Dekker 1971, with Veltkamp's split; needs only correctly rounded
// multiply and add, which Vulkan guarantees).
void twoProduct(float a, float b, out float p, out float e) {
    precise float pp = a * b;
    precise float ca = 4097.0 * a;
    precise float ah = ca - (ca - a);
    precise float al = a - ah;
    precise float cb = 4097.0 * b;
    precise float bh = cb - (cb - b);
    precise float bl = b - bh;
    precise float ee = ((ah * bh - pp) + ah * bl + al * bh) + al * bl;
    p = pp;
    e = ee;
}

// The next float from q towards +inf (dir > 0) or -inf; q finite and non-zero.
float nextFloat(float q, float dir) {
    const uint bits = floatBitsToUint(q);
    return uintBitsToFloat((q > 0.0) == (dir > 0.0) ? bits + 1u : bits - 1u);
}

// a - q b (division a / b) or a - q q (square root of a; b unused), to compare candidate
// results: exact up to the last subtraction's rounding, far below the difference between
// neighbouring candidates.
float signedResidual(bool root, float a, float b, float q) {
    float p, e;
    twoProduct(q, root ? q : b, p, e);
    precise float r = (a - p) - e;
    return r;
}

// The smaller of the gaps between q and its two neighbouring floats (q finite, non-zero).
float minGap(float q) {
    precise float up = nextFloat(q, 1.0) - q;
    precise float down = q - nextFloat(q, -1.0);
    return min(abs(up), abs(down));
}

// The device's result q of a / b or sqrt(a), correctly rounded. Pass 0 checks q: it is the
// correctly rounded result when its residual is under boundFactor * scale * gap (the usual
// case: one exact product). A lane that fails walks on, one neighbour per pass in the
// direction the residual's sign gives, while the residual shrinks, at most `steps` ulp. One
// residual per pass: drivers that run shaders as masked SIMD code (lavapipe) run a loop's
// first pass for every lane, so the check is all an exact device pays.
float correctlyRounded(bool root, float a, float b, float q, float boundFactor, int steps) {
    float best = q, bestR = 0.0, dir = 0.0;
    for (int i = 0; i <= steps; ++i) {
        const float sr = signedResidual(root, a, b, q);
        const float r = abs(sr);
        if (i == 0) {
            precise float bound = boundFactor * (root ? q : abs(b)) * minGap(q);
            if (r < bound) break;
            dir = (sr > 0.0) == (root || b > 0.0) ? 1.0 : -1.0;  // towards the exact result
        } else if (!(r < bestR)) {
            break;
        }
        best = q;
        bestR = r;
        q = nextFloat(q, dir);
    }
    return best;
}

// a / b correctly rounded (IEEE), from an approximation q of it (within a few ulp). q is the
// correctly rounded quotient when |a - q b| < |b| gap / 2 (gap: the smaller distance to q's
// neighbours; tested against 0.49, a little under half).
float crDivFrom(float a, float b, float q) {
    if (isinf(q) || isnan(q) || q == 0.0) return q;
    return correctlyRounded(false, a, b, q, 0.49, 3);
}
// From the device's quotient: Vulkan allows 2.5 ulp, and compilers may turn a division into
// a multiplication by the reciprocal.
float crDiv(float a, float b) {
    precise float q = a / b;
    return crDivFrom(a, b, q);
}

// sqrt(x) correctly rounded, from an approximation s of it. s is correctly rounded when
// |x - s^2| < s gap, as (s +- gap / 2)^2 = s^2 +- s gap + gap^2 / 4 (tested against
// 0.98 s gap).
float crSqrtFrom(float x, float s) {
    if (!(x > 0.0) || isinf(x)) return s;
    return correctlyRounded(true, x, 0.0, s, 0.98, 2);
}
// From the device's square root (Vulkan: "inherited from 1 / inversesqrt").
float crSqrt(float x) {
    precise float s = sqrt(x);
    return crSqrtFrom(x, s);
}

// ssfx::toUnorm8: v in [0, 1] (NaN: 0) to round-half-up(v * 255), with the product exact:
// v = M 2^-s with a 24-bit M, so v * 255 = (255 M) 2^-s and 255 M fits in 32 bits.
uint toUnorm8(float v) {
    if (!(v > 0.0)) return 0u;
    if (v >= 1.0) return 255u;
    int e;
    const float f = frexp(v, e);  // v = f 2^e, f in [0.5, 1)
    const uint m = uint(ldexp(f, 24));
    const int s = 24 - e;  // v = m 2^-s, s >= 24 (e <= 0)
    if (s >= 33) return 0u;  // v * 255 < 2^32 2^-33 = 0.5
    const uint q = m * 255u;
    // floor(q 2^-s + 0.5) = (q >> s) + bit s - 1 of q
    return (s == 32 ? 0u : q >> uint(s)) + ((q >> uint(s - 1)) & 1u);
}


// k / 4080 correctly rounded to float32 for k = 0..4080 (ssfx::kSixteenthLevels; v / 255 is
// level(16 v)): no table (on lavapipe a lookup at a per-pixel index is a loop over the SIMD
// lanes) and no division. 4080 = 2^20 (1 - 2^-16) / 257, so k / 4080 = w (1 + 2^-16 + 2^-32
// + ...) with w = 257 k 2^-20, exact in float32 (257 k < 2^24). w + (w 2^-16 + w 2^-32) has
// two roundings, both far below half an ulp of the result, and k / 4080 is never near a
// rounding boundary (its bits past the 24th repeat an 8-bit pattern), so the sum rounds to
// the correctly rounded quotient: checked for every k against the CPU's table by
// GpuShaders.ExactHelpersMatchIeee (and offline with IEEE float32 arithmetic).
float levelOver4080(uint k) {
    precise float w = float(k * 257u) * (1.0 / 1048576.0);
    precise float tail = w * (1.0 / 65536.0) + w * (1.0 / 4294967296.0);
    precise float r = w + tail;
    return r;
}
