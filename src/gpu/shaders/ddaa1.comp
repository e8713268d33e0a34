#version 450
// ddaa1: directional diffusion without edge search (Klein, DDAA, sections 2.1-2.2; spec
// ppaa.md "ddaa1"; the CPU's src/aa/ddaa1.cpp).
#define SSFX_TILE
#include "ppaa.glsl"
#include "ddaa.glsl"

void main() {
    loadTile();
    ivec2 p;
    if (!outputPixel(p)) return;
    const Luma3x3 n = neighbourhood(p.x, p.y);
    float range;
    vec3 colour = texelValue(p.x, p.y);  // the input pixel unless an edge is found
    if (!belowEdgeThreshold(n, range)) colour = diffuse(p.x, p.y, diffusion(n, edgeSides(n)), 0.0, 0.0);
    store(p, colour, alphaAt(p.x, p.y));
}
