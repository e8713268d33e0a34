// Per-pixel pieces of DDAA shared by ddaa1 and ddaa2 (Klein, DDAA, sections 2.1-2.2; the
// CPU's src/aa/ddaa_kernel.hpp).

struct Diffusion {
    float dirX, dirY;  // unit edge vector
    float strength;
};

Diffusion diffusion(Luma3x3 n, EdgeSides s) {
    // Scharr kernel (Jaehne et al. 1999; paper section 2.1).
    const float k1 = 162.0 / 256.0, k2 = 47.0 / 256.0;
    precise float Dx = (n.W * k1 + n.SW * k2 + n.NW * k2) - (n.E * k1 + n.SE * k2 + n.NE * k2);
    precise float Dy = (n.S * k1 + n.SW * k2 + n.SE * k2) - (n.N * k1 + n.NW * k2 + n.NE * k2);
    precise float ex = -Dy;
    precise float ey = Dx;  // along the edge, perpendicular to the gradient
    precise float len2 = ex * ex + ey * ey;
    const float len = crSqrt(len2);
    precise float raw = pc.strength * crSqrt(len);
    Diffusion d = Diffusion(0.0, 0.0, 0.0);
    if (!(raw < 1e-6)) {
        d.strength = minf(1.0, raw);
        d.dirX = crDiv(ex, len);
        d.dirY = crDiv(ey, len);
    }
    // Ridge or valley (a thin line): diffuse less the steeper it is (section 2.2).
    if ((s.g1 > 0.0) == (s.g2 > 0.0)) {
        precise float k = 1.0 - minf(1.0, pc.ridgeFactor * minf(abs(s.g1), abs(s.g2)));
        precise float st = d.strength * k;
        d.strength = st;
    }
    return d;
}

// Average of two bilinear reads at centre -/+ step (+ offset), step = dir * maxDiffusion *
// strength pixels; (offU, offV) is the edge-search offset in texture units.
vec3 diffuse(int x, int y, Diffusion d, float offU, float offV) {
    precise float sx = d.dirX * pc.maxDiffusion * d.strength;
    precise float sy = d.dirY * pc.maxDiffusion * d.strength;
    const float u = centreU(x), v = centreV(y);
    precise float du = sx * pc.invW;
    precise float dv = sy * pc.invH;
    precise float au = u - du + offU;
    precise float av = v - dv + offV;
    precise float bu = u + du + offU;
    precise float bv = v + dv + offV;
    const vec3 a = sampleUV(au, av);
    const vec3 b = sampleUV(bu, bv);
    precise vec3 r = (a + b) * 0.5;
    return r;
}
