#pragma once
// report.html: the calibration report as one self-contained page a lab can share. Per sample
// the headline of each method, the warnings, the consistency diagnostics, the
// posterior-predictive check and the evidence; the plots inline as SVG; the provenance. Built
// from summary.json's content and the SVG files of the same report folder, so that it says
// nothing the files do not.
#include <filesystem>

#include <nlohmann/json.hpp>

namespace rbcal::calibration {

// Writes folder/report.html from the report's summary (report_summary.hpp) and the SVG plots
// already in folder.
void write_report_html(const nlohmann::json& summary, const std::filesystem::path& folder);

}  // namespace rbcal::calibration
