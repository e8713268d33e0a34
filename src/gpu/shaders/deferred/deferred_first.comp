#version 450
// Adaptive shading, pass 1 (adaptive_ss.md, ShadeFirstSample): the sample of dither index 0
// of every pixel's window, standing for the whole pixel (footprint 1), into S with its luma
// (for the shading metric). Brute force does not run it.
#include "deferred.glsl"

void main() {
    ivec2 p;
    if (!pixelOf(p)) return;
    const vec3 c = shadeSample(windowSample(p, 0), 1.0);
    imageStore(firstImage, p, vec4(c, lumaOf(c)));
}
