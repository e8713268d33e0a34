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

// |a - q b| (division a / b) or |a - q q| (square root of a; b unused), to compare
// candidate results: exact up to the last subtraction's rounding, far below the difference
// between neighbouring candidates.
float residual(bool root, float a, float b, float q) {
    float p, e;
    twoProduct(q, root ? q : b, p, e);
    precise float r = (a - p) - e;
    return abs(r);
}

// The smaller of the gaps between q and its two neighbouring floats (q finite, non-zero).
float minGap(float q) {
    precise float up = nextFloat(q, 1.0) - q;
    precise float down = q - nextFloat(q, -1.0);
    return min(abs(up), abs(down));
}

// The device's result q of a / b or sqrt(a), correctly rounded: kept when its residual r
// shows it is (the usual case: one exact product), else moved to a neighbour while that
// one has the smaller residual, at most `steps` times.
float correctlyRounded(bool root, float a, float b, float q, float r, int steps) {
    for (int i = 0; i < steps; ++i) {
        const float up = nextFloat(q, 1.0), down = nextFloat(q, -1.0);
        const float ru = residual(root, a, b, up), rd = residual(root, a, b, down);
        if (ru < r && ru <= rd) {
            q = up;
            r = ru;
        } else if (rd < r) {
            q = down;
            r = rd;
        } else {
            break;
        }
    }
    return q;
}

// a / b correctly rounded (IEEE), from an approximation q of it (within a few ulp). q is the
// correctly rounded quotient when |a - q b| < |b| gap / 2 (gap: the smaller distance to q's
// neighbours; tested against 0.49, a little under half).
float crDivFrom(float a, float b, float q) {
    if (isinf(q) || isnan(q) || q == 0.0) return q;
    const float r = residual(false, a, b, q);
    precise float bound = 0.49 * abs(b) * minGap(q);
    return r < bound ? q : correctlyRounded(false, a, b, q, r, 3);
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
    const float r = residual(true, x, 0.0, s);
    precise float bound = 0.98 * s * minGap(s);
    return r < bound ? s : correctlyRounded(true, x, 0.0, s, r, 2);
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
// level(16 v)), in integer arithmetic only: no table (on lavapipe a lookup at a per-pixel
// index is a loop over the SIMD lanes), no division, no rounding by the device.
// Since 2^28 = 255 * 0x101010 + 16, floor(k' 2^32 / 4080) = k' 0x101010 + floor(16 k' / 255);
// k' = k 2^sh is normalised to k' >= 2^10, so that floor has 31 or 32 bits. Its low bit is
// made sticky when the division leaves a remainder; it is then rounded half to even to 24
// bits, and the float of that significand times a power of two is exact. (Checked against
// the CPU's table for every k by GpuShaders.ExactHelpersMatchIeee.)
float levelOver4080(uint k) {
    if (k == 0u) return 0.0;
    if (k >= 4080u) return 1.0;
    const int sh = max(0, 10 - findMSB(k));
    const uint kp = k << uint(sh);
    const uint n = 16u * kp;
    const uint q = (n * 0x8081u) >> 23u;  // floor(n / 255), exact for n < 65535
    const uint m = (kp * 0x101010u + q) | (n != 255u * q ? 1u : 0u);
    const int d = findMSB(m) - 23;  // 7 or 8 bits to drop
    const uint low = m & ((1u << uint(d)) - 1u), tie = 1u << uint(d - 1);
    const uint mant = (m >> uint(d)) + (low > tie || (low == tie && ((m >> uint(d)) & 1u) != 0u) ? 1u : 0u);
    // mant <= 2^24 converts exactly; 2^(d - 32 - sh) lies in [2^-35, 2^-24]: an exact product.
    precise float r = float(mant) * uintBitsToFloat(uint(127 + d - 32 - sh) << 23u);
    return r;
}
