#pragma once
// Display units. Internally everything is SI (G_s in N/m, lengths in m, viscosities in Pa s);
// reports, files and options give G_s in uN/m, cell radii in um and viscosities in mPa s.
namespace rbcal {

inline constexpr double kMicro = 1e6;  // N/m -> uN/m, m -> um
inline constexpr double kMilli = 1e3;  // Pa s -> mPa s

}  // namespace rbcal
