// Exact float helpers of the model sampling mode (ppaa.glsl's header says why): correctly
// rounded division (with Dekker's exact product) and square root (with an integer residual)
// from the device's results, and the exact float-to-8-bit conversion. Self-contained (no
// bindings): tests/gpu/shaders/exact.comp checks them against the CPU's IEEE results.

// a * b == p + e exactly (Dekker 1971, with Veltkamp's split; needs only correctly rounded
// multiply and add, which Vulkan guarantees), for |a|, |b| < 2^114 (4097 a must not
// overflow) and a product that neither overflows nor underflows.
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

// a + b == s + e exactly (Knuth's two-sum; correctly rounded add and subtract only).
void twoSum(float a, float b, out float s, out float e) {
    precise float ss = a + b;
    precise float bb = ss - a;
    precise float ee = (a - (ss - bb)) + (b - bb);
    s = ss;
    e = ee;
}

// Float pairs hi + lo (|lo| at most half an ulp of hi): about 48 significant bits from float
// arithmetic alone, for the few values that must agree with the CPU's double (the AO passes'
// depth -> z). Products and sums of pairs keep about 46 bits.
vec2 pairFrom(float s, float e) {  // renormalised: |e| <= ulp(s) / 2 after
    float hi, lo;
    twoSum(s, e, hi, lo);
    return vec2(hi, lo);
}
vec2 pairAdd(vec2 a, vec2 b) {
    float s, e;
    twoSum(a.x, b.x, s, e);
    precise float t = e + (a.y + b.y);
    return pairFrom(s, t);
}
vec2 pairMul(vec2 a, vec2 b) {
    float p, e;
    twoProduct(a.x, b.x, p, e);
    precise float t = e + (a.x * b.y + a.y * b.x);
    return pairFrom(p, t);
}
// a / b rounded to float: q1 the correctly rounded quotient of the high parts, q2 the
// remainder's share; q1 + q2 is a / b within about 2^-46, and its one float rounding is the
// correctly rounded quotient except where a / b lies that close to a rounding boundary.
float crDiv(float a, float b);
float pairDivToFloat(vec2 a, vec2 b) {
    const float q1 = crDiv(a.x, b.x);
    float p, e;
    twoProduct(q1, b.x, p, e);
    precise float r = (((a.x - p) - e) + a.y) - q1 * b.y;
    precise float q = q1 + r / b.x;
    return q;
}

// The next float from q towards +inf (dir > 0) or -inf; q finite and non-zero.
float nextFloat(float q, float dir) {
    const uint bits = floatBitsToUint(q);
    return uintBitsToFloat((q > 0.0) == (dir > 0.0) ? bits + 1u : bits - 1u);
}

// a - q b, to compare candidate quotients: exact up to the last subtraction's rounding, far
// below the difference between neighbouring candidates.
float signedResidual(float a, float b, float q) {
    float p, e;
    twoProduct(q, b, p, e);
    precise float r = (a - p) - e;
    return r;
}

// The smaller of the gaps between q and its two neighbouring floats (q finite, non-zero).
float minGap(float q) {
    precise float up = nextFloat(q, 1.0) - q;
    precise float down = q - nextFloat(q, -1.0);
    return min(abs(up), abs(down));
}

// The device's quotient q of a / b, correctly rounded. Pass 0 checks q: it is the correctly
// rounded result when its residual is under boundFactor |b| gap (the usual case: one exact
// product). A lane that fails walks on, one neighbour per pass in the
// direction the residual's sign gives, while the residual shrinks, at most `steps` ulp. One
// residual per pass: drivers that run shaders as masked SIMD code (lavapipe) run a loop's
// first pass for every lane, so the check is all an exact device pays.
float correctlyRounded(float a, float b, float q, float boundFactor, int steps) {
    float best = q, bestR = 0.0, dir = 0.0;
    for (int i = 0; i <= steps; ++i) {
        const float sr = signedResidual(a, b, q);
        const float r = abs(sr);
        if (i == 0) {
            precise float bound = boundFactor * abs(b) * minGap(q);
            if (r < bound) break;
            dir = (sr > 0.0) == (b > 0.0) ? 1.0 : -1.0;  // towards the exact result
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
    return correctlyRounded(a, b, q, 0.49, 3);
}
// From the device's quotient: Vulkan allows 2.5 ulp, and compilers may turn a division into
// a multiplication by the reciprocal.
float crDiv(float a, float b) {
    precise float q = a / b;
    return crDivFrom(a, b, q);
}

// sqrt(x) correctly rounded, from an approximation s of it (within 8 ulp), in integer
// arithmetic. With x = X 2^(ex - 23) and s = S 2^(es - 23) (24-bit X, S), s is correctly
// rounded when (S - 1/2)^2 < X 2^(ex - 2 es + 23) < (S + 1/2)^2, that is, times 4, when
// (2S - 1)^2 < N < (2S + 1)^2 with N = X 2^(ex - 2 es + 25): with E = N - 4 S^2, when
// -4S < E <= 4S (N and 4 S^2 are even; a tie, N = (2S +- 1)^2, would be odd; for S = 2^23
// the bound below is -2S, sqrtStep). N reaches 2^51, but E is small (8 S t for s t ulp off:
// under 2^31 within 8 ulp), so E is exact in wrapping 32-bit arithmetic. One check, a step of round(E / 8S) ulp (the correction to
// first order), a second check and a last step of one ulp (the first-order step can end
// one ulp off): no float residual, no loop. (s, then every step, stays within the range
// where sqrt of a normal float lies, so the shift is 24..27.)
int sqrtResidual(uint X, int ex, uint bits, out int fourS) {
    const uint S = (bits & 0x7fffffu) | 0x800000u;
    const int shift = clamp(ex - 2 * int(bits >> 23u) + 152, 0, 31);  // biased: + 2 127 - 127 + 25
    fourS = int(S << 2u);
    return int((X << uint(shift)) - ((S * S) << 2u));
}
uint sqrtStep(uint X, int ex, uint bits, bool firstOrder) {
    int fourS;
    const int e = sqrtResidual(X, ex, bits, fourS);
    if (firstOrder) {
        // The step as a float addition, t ulp of s: exact, or rounded to the next binade's
        // ulp where it crosses a power of two (a step in bits would be twice too long there).
        const float t = round(float(e) / float(2 * fourS));
        precise float moved = uintBitsToFloat(bits) + t * (uintBitsToFloat(bits & 0x7f800000u) * (1.0 / 8388608.0));
        return floatBitsToUint(moved);
    }
    // Below a power of two (S = 2^23) the next float down is half an ulp away: the bound
    // is (S - 1/4)^2, so E > -2S.
    const int below = (bits & 0x7fffffu) == 0u ? fourS / 2 : fourS;
    return e > fourS ? bits + 1u : (e <= -below ? bits - 1u : bits);
}
float crSqrtFrom(float x, float s) {
    if (!(x > 0.0) || isinf(x)) return s;
    // A subnormal x: the root of x 2^24 (normal), times 2^-12 (exact: the root is normal).
    const bool tiny = x < 1.17549435e-38;  // 2^-126
    precise float xs = x * 16777216.0;
    const float xn = tiny ? xs : x;
    const float sn = tiny ? sqrt(xn) : s;
    const uint bx = floatBitsToUint(xn);
    const uint X = (bx & 0x7fffffu) | 0x800000u;
    const int ex = int(bx >> 23u);
    const uint bits = sqrtStep(X, ex, sqrtStep(X, ex, floatBitsToUint(sn), true), false);
    precise float r = uintBitsToFloat(bits) * (tiny ? 1.0 / 4096.0 : 1.0);
    return r;
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
