#pragma once
// Whether a windowed average is stationary: the window's late half against its early half,
// drift = ln(mean_late / mean_early). Its sd is twice the whole window's relative blocking
// error, the run's eta_re_sem / eta_re (each half's mean has sqrt(2) times the whole's error):
// the whole window reaches longer blocks than either half, whose own blocking errors fall
// short on slow series.
// A stationary run keeps |drift| within a few sd; a run still relaxing (dense suspensions
// whose seeded layers dissolve over tens of strain units) or one with fluctuations slower than
// the blocking can see shows more, and then its blocking error understates its error.
#include <nlohmann/json.hpp>
#include <vector>

namespace rbcal::solver {

struct WindowDrift {
  bool available = false;  // false: fewer than 16 samples per half, or a mean not positive
  double drift = 0.0;      // ln(mean of the late half / mean of the early half)
  double sd = 0.0;         // 2 x the window's relative blocking error
  double z() const { return sd > 0.0 ? drift / sd : 0.0; }
};

// |z| beyond this, and a drift beyond kDriftFloor, is reported as a window not stationary.
inline constexpr double kDriftZ = 3.0;
inline constexpr double kDriftFloor = 0.02;

// The drift of a window's series (its samples in order), given the relative standard error of
// the whole window's mean; not available below 32 samples.
WindowDrift window_drift(const std::vector<double>& series, double relative_sem);

// Beyond kDriftZ sd and kDriftFloor: the window is not stationary.
bool drifts(const WindowDrift& d);

// The drift a result block (result.json's "result") records; not available in results
// written before the field.
WindowDrift drift_of_result(const nlohmann::json& result);

}  // namespace rbcal::solver
