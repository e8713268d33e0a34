// The sRGB transfer in the device's own arithmetic (IEC 61966-2-1's inverse EOTF, as the
// CPU's linearToSrgb), shared by the passes (ppaa.glsl) and the decode probe.
//
// Linear light to the nearest 8-bit sRGB level, computed with the device's pow: the hardware
// mode's encode (as a GPU writing an sRGB target converts, to the device's precision), and
// how the model recovers a texel's byte from an sRGB view's decoded value. The latter needs
// only the device's decode and this to land within half a level of the byte, which the
// pass's probe checks for all 256 values when it is made (aa_pass.cpp: srgbBytesRecovered).
uint srgbLevelDevice(float linear) {
    const float l = clamp(linear, 0.0, 1.0);
    const float e = l <= 0.0031308 ? l * 12.92 : 1.055 * pow(l, 1.0 / 2.4) - 0.055;
    return uint(clamp(round(e * 255.0), 0.0, 255.0));
}
uvec3 srgbLevelsDevice(vec3 linear) {
    return uvec3(srgbLevelDevice(linear.r), srgbLevelDevice(linear.g), srgbLevelDevice(linear.b));
}
