// Tinted relief: a colour-relief colour blended with the grey (or RGB) shaded relief, both
// as displayed (code value / 255), as a cartographer's layers blend in a GIS:
//  * multiply: colour × relief, at weight W (a GIS layer's opacity): c·(1 − W + W·r). With the linear tone of grey reliefs (products.h
//    ToneCurve) the relief is proportional to the light, so this is the colour as albedo
//    lit by it; under the sRGB curve, nearly a power law, it is close to the product in
//    linear light too;
//  * soft light (W3C Compositing and Blending Level 1, "soft-light": backdrop = the colour,
//    source = the relief), mixed with the colour by weight W: W·B(c, s) + (1 − W)·c. A
//    relief value of 0.5 leaves the colour unchanged.
#pragma once

namespace skylit::relief {

enum class TintBlend { Multiply, SoftLight };

// W3C soft-light B(cb, cs) for a backdrop cb and source cs in 0…1.
double soft_light(double backdrop, double source);
// colour·(1 − W + W·relief), W = weight in 0…1.
double multiply_mix(double colour, double relief, double weight);
// W·soft_light(colour, relief) + (1 − W)·colour; weight in 0…1.
double soft_light_mix(double colour, double relief, double weight);

}  // namespace skylit::relief
