// Tinted relief: a colour-relief colour blended with the grey (or RGB) shaded relief.
//  * multiply: the colour is the surface albedo in linear light, radiance = albedo × the
//    relief's radiance (the physically right tint; flat lit ground shows the colour darkened
//    by its irradiance);
//  * soft light (W3C Compositing and Blending Level 1, "soft-light": backdrop = the colour,
//    source = the relief, both sRGB-encoded 0…1), mixed with the colour by weight W:
//    W·B(c, s) + (1 − W)·c. A relief value of 0.5 leaves the colour unchanged.
#pragma once

namespace skylit::relief {

enum class TintBlend { Multiply, SoftLight };

// Linear light of an sRGB-encoded value in 0…1 (IEC 61966-2-1).
double srgb_to_linear(double encoded);
// W3C soft-light B(cb, cs) for a backdrop cb and source cs in 0…1.
double soft_light(double backdrop, double source);
// W·soft_light(colour, relief) + (1 − W)·colour; weight in 0…1.
double soft_light_mix(double colour, double relief, double weight);

}  // namespace skylit::relief
