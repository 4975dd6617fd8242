// Float32 GPU vs double CPU reference: the tolerances every GPU-vs-reference test uses,
// with their derivations (observed values are printed by gpu_products_test and
// gpu_lighting_test).
#pragma once

namespace skylit::gpu::tolerance {

// horizon ≤ 0.05°: the GPU samples float B-spline coefficients with float weights and
// float positions; heights of ~2 km carry ~1e-4 m of rounding, positions ~1e-5 texel
// times slopes ≤ ~3, over the shortest lever (t_0 ≈ one texel ≥ 20 m): ≤ ~1e-5 rad ≈
// 6e-4°. The smooth max and atan add rounding of the same order. Observed max ≈ 1.1e-3°;
// 0.05° leaves room for other drivers' atan and fused multiply-adds.
inline constexpr double kHorizonTolDeg = 0.05;
// svf ≤ 2e-3, skyview ≤ 2e-3: means over azimuths of terms whose derivative in σ is ≤ 1
// (svf) or ≤ 1/π·2π/W·W = 2 (skyview), so |Δ| ≤ 2·|Δσ| ≈ 7e-5 from the horizon bound;
// the Horn normal in float (differences against the centre height) adds ~1e-6.
// Observed ≤ 1.6e-6.
inline constexpr double kSvfTol = 2e-3;
inline constexpr double kSkyviewTol = 2e-3;
// shaded ≤ 1 code value on ≥ kMinFraction of texels (and ≤ 2 on all): V·T in float
// differs from double by ~1e-5 relative (16 SH coefficients summed from 2W wedge terms),
// i.e. ≤ ~0.005 code values, so only texels within that of a rounding boundary of the
// 8-bit code move, and by one. Lit shaded: the same, plus penumbra texels.
inline constexpr double kShadedTolCodes = 1.0;
inline constexpr double kShadedMaxCodes = 2.0;
inline constexpr double kMinFraction = 0.99;
// shadow ≤ 0.02 on ≥ kMinFraction of texels (≤ 0.25 on all): the sun's horizon σ is a
// max of slopes from float heights with the receiver's height subtracted before
// interpolating and the step offset kept apart from the texel index, so a slope carries
// ~1e-7 relative rounding (~1e-6 rad); in the disc frame (units of the 0.00465 rad
// radius) that is ~2e-4, and the fraction's derivative is ≤ 2/π, so |Δ| ~1e-4. The
// tangent-plane line (float Horn normal, asin) adds the same order; the disc-polygon
// area in float ~1e-6. 0.02 leaves two decades for drivers' atan, asin and fused
// multiply-adds; the rare texel whose max switches between two nearly equal steps
// stays within the 1 %.
inline constexpr double kShadowTol = 0.02;
inline constexpr double kShadowMaxAll = 0.25;
// irradiance relative ≤ 1e-3 on ≥ kMinFraction of lit texels, |Δ| ≤ 1e-3·E + 0.02·DNI on
// all: the sky part π·V·T(n) is ~1e-5 relative in float (the shaded bound); the sun part
// DNI·max(n·s, 0)·shadow has only the shadow fraction as a loose factor.
inline constexpr double kIrradianceRelTol = 1e-3;

}  // namespace skylit::gpu::tolerance
