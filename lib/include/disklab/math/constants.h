#pragma once
#include <numbers>

namespace disklab::math {
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kHalfPi = std::numbers::pi / 2.0;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Largest double below 1: what a [0,1) generator may return at most.
inline constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;
}  // namespace disklab::math
