// Sums over the frames of a time series (time_series.h): the trapezoid rule on the
// frames' own, possibly uneven, instants.
//
//   insolation (Wh/m²) = Σ_k w_k · E_k      E_k irradiance of frame k, W/m²
//   sun hours  (h)     = Σ_k w_k · s_k      s_k visible fraction of the solar disc
//                                           (the shadow product) while the sun is
//                                           above the horizon (sun_above_horizon),
//                                           else 0
//
// The integral covers [first, last] frame; values between frames are taken as linear.
#pragma once

#include "shading/sky/atmosphere.h"
#include "shading/sky/time_utc.h"

#include <span>
#include <vector>

namespace skylit::shading {

// Trapezoid weights in hours: w_0 = (t_1 − t_0)/2, w_k = (t_{k+1} − t_{k−1})/2,
// w_n = (t_n − t_{n−1})/2 (one instant: a single weight 0, no interval). Throws
// std::invalid_argument unless the instants strictly increase.
std::vector<double> trapezoid_weights_hours(std::span<const sky::UtcTime> instants);

// Whether a frame's sun counts for sun hours: its centre above the apparent
// horizon, exactly where its DNI is non-zero (atmosphere.h), so sun hours and the
// direct part of insolation agree on when the sun shines.
bool sun_above_horizon(const sky::Sun& sun);

}  // namespace skylit::shading
