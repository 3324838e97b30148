// How far the points of a growth fit may stray from its line before the power law is said not to
// fit (scaling/power_fit.cpp decides it; scaling/scaling_text.cpp says it in the fit's words, so
// a fit with a low r² that still "fits" says why: a flat line has little variance to explain).
#pragma once

namespace raygate {

// Residual standard deviation in ln units above which the points are called scattered (±15%).
inline constexpr double kScatterLimit = 0.15;

}  // namespace raygate
