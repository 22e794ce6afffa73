#pragma once
// summary.json of a calibration report (schema "rbcal.calibration_report/1"): per sample eta0
// with its error, G_s by each method with its interval (uN/m), lambda when fitted, the MCMC's
// diagnostics, alpha per shear rate with R^2, G_s per Ca, points used and skipped with reasons,
// the sample comparison, and provenance (rbcal version and git revision, data and surrogate
// files, options, seed). Units are in the key names (_uN_per_m, _mPa_s, _per_s).
#include <filesystem>
#include <nlohmann/json.hpp>

#include "calibration/calibration_report.hpp"

namespace rbcal::calibration {

nlohmann::json sample_summary(const SampleReport& sample);
// summary.json's "joint" (the joint posterior over samples) and "comparison" (a G_s ratio).
nlohmann::json joint_summary(const JointReport& joint);
nlohmann::json comparison_summary(const SampleComparisonReport& comparison);

// The whole summary; files and plots describe what write_calibration_report wrote.
nlohmann::json report_summary(const CalibrationReport& report, const ReportFiles& files);

}  // namespace rbcal::calibration
