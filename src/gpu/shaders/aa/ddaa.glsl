// Per-pixel pieces of DDAA shared by ddaa1 and ddaa2 (Klein, DDAA, sections 2.1-2.2; the
// CPU's src/aa/ddaa_kernel.hpp).

struct Diffusion {
    float dirX, dirY;  // unit edge vector
    float strength;
};

Diffusion diffusion(Luma3x3 n, EdgeSides s) {
    // Scharr kernel (Jaehne et al. 1999; paper section 2.1).
    const float k1 = 162.0 / 256.0, k2 = 47.0 / 256.0;
    EXACT float Dx = (n.W * k1 + n.SW * k2 + n.NW * k2) - (n.E * k1 + n.SE * k2 + n.NE * k2);
    EXACT float Dy = (n.S * k1 + n.SW * k2 + n.SE * k2) - (n.N * k1 + n.NW * k2 + n.NE * k2);
    EXACT float ex = -Dy;
    EXACT float ey = Dx;  // along the edge, perpendicular to the gradient
    EXACT float len2 = ex * ex + ey * ey;
    const float len = squareRoot(len2);
    EXACT float raw = pc.strength * squareRoot(len);
    Diffusion d = Diffusion(0.0, 0.0, 0.0);
    if (!(raw < 1e-6)) {
        d.strength = minf(1.0, raw);
        d.dirX = divide(ex, len);
        d.dirY = divide(ey, len);
    }
    // Ridge or valley (a thin line): diffuse less the steeper it is (section 2.2).
    if ((s.g1 > 0.0) == (s.g2 > 0.0)) {
        EXACT float k = 1.0 - minf(1.0, pc.ridgeFactor * minf(abs(s.g1), abs(s.g2)));
        EXACT float st = d.strength * k;
        d.strength = st;
    }
    return d;
}

// Average of two bilinear reads at centre -/+ step (+ offset), step = dir * maxDiffusion *
// strength pixels; centre is the pixel's centre (centreU, centreV: its caller's, so that ddaa2
// divides once for the search and the diffusion), (offU, offV) the edge-search offset in
// texture units.
vec3 diffuse(vec2 centre, Diffusion d, float offU, float offV) {
    EXACT float sx = d.dirX * pc.maxDiffusion * d.strength;
    EXACT float sy = d.dirY * pc.maxDiffusion * d.strength;
    const float u = centre.x, v = centre.y;
    EXACT float du = sx * pc.invW;
    EXACT float dv = sy * pc.invH;
    EXACT float au = u - du + offU;
    EXACT float av = v - dv + offV;
    EXACT float bu = u + du + offU;
    EXACT float bv = v + dv + offV;
    const vec3 a = sampleUV(au, av);
    const vec3 b = sampleUV(bu, bv);
    EXACT vec3 r = (a + b) * 0.5;
    return r;
}
