#version 450
// ddaa1: directional diffusion without edge search (Klein, DDAA, sections 2.1-2.2; spec
// ppaa.md "ddaa1"; the CPU's src/aa/ddaa1.cpp).
#define SSFX_TILE
#include "ppaa.glsl"
#include "ddaa.glsl"

bool edgeAt(int x, int y, Luma3x3 n) { return edgeAt3x3(n); }
vec3 edgeColour(int x, int y, Luma3x3 n) {
    return diffuse(vec2(centreU(x), centreV(y)), diffusion(n, edgeSides(n)), 0.0, 0.0);
}

#include "edge_list.glsl"
