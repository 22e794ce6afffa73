#pragma once
// Display units of the calibration's reports. Internally everything is SI (G_s in N/m,
// lengths in m, viscosities in Pa s); reports print G_s in uN/m, cell radii in um and
// viscosities in mPa s.
namespace rbcal::calibration {

inline constexpr double kMicro = 1e6;  // N/m -> uN/m, m -> um
inline constexpr double kMilli = 1e3;  // Pa s -> mPa s

}  // namespace rbcal::calibration
