#pragma once
// Display units of the calibration's reports. Internally everything is SI (G_s in N/m,
// lengths in m); reports print G_s in uN/m and cell radii in um.
namespace rbcal::calibration {

inline constexpr double kMicro = 1e6;  // N/m -> uN/m, m -> um

}  // namespace rbcal::calibration
