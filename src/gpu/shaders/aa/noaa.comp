#version 450
// noaa: the input unchanged (the baseline every method should beat).
#include "ppaa.glsl"

void main() {
    ivec2 p;
    if (!outputPixel(p)) return;
    storeInput(p);
}
