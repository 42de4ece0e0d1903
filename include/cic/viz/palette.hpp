#pragma once
// Colours shared by the viewer and (by value) the POV-Ray materials in src/io/povray.cpp.
#include <array>

namespace cic::viz {

using Rgb = std::array<float, 3>;

inline constexpr Rgb kChassisColour = {0.92f, 0.55f, 0.12f};   // orange
inline constexpr Rgb kPanelColour = {0.20f, 0.40f, 0.85f};     // blue
inline constexpr Rgb kGroundLight = {0.82f, 0.82f, 0.80f};
inline constexpr Rgb kGroundDark = {0.62f, 0.64f, 0.67f};
inline constexpr Rgb kGridLine = {0.35f, 0.37f, 0.40f};
inline constexpr Rgb kSky = {0.62f, 0.74f, 0.92f};
inline constexpr Rgb kTrail = {0.85f, 0.05f, 0.55f};          // magenta: the centre's path on the ground
inline constexpr Rgb kTrailStart = {0.10f, 0.55f, 0.20f};     // green: the ring where the path starts

} // namespace cic::viz
