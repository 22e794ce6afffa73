#pragma once
// Rheometer measurements as read from a CSV file (docs/reference.md, "Rheometer CSV"):
//   sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n
// one row per mean value, kind `plasma` or `suspension`, several samples per file,
// `#` lines for provenance. Viscosities are converted to SI (Pa s) on reading.
// A sample without measured plasma rows may give one `plasma_assumed` row instead: phi 0,
// shear rate 0 (none), viscosity_mPa_s the assumed eta0 and sd_mPa_s its standard
// deviation (> 0), which the calibration integrates over and reports as assumed.
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace rbcal::calibration {

enum class MeasurementKind { plasma, suspension, plasma_assumed };

struct RheometerRow {
  std::string sample;
  MeasurementKind kind = MeasurementKind::suspension;
  double phi = 0.0;           // volume fraction (0 for plasma)
  double shear_rate = 0.0;    // [1/s]
  double viscosity = 0.0;     // mean viscosity [Pa s]
  double viscosity_sd = 0.0;  // standard deviation of the n repeats [Pa s]
  int repeats = 1;            // n
  int line = 0;               // 1-based line in the source file
};

struct RheometerData {
  std::string source;                   // file name used in messages
  std::vector<std::string> provenance;  // the `#` comment lines, without the `#`
  std::vector<RheometerRow> rows;
  std::vector<std::string> sample_names() const;  // in order of first appearance
};

// A malformed input: the message reads "FILE:LINE: field FIELD: what is wrong".
class RheometerDataError : public std::runtime_error {
 public:
  RheometerDataError(const std::string& file, int line, const std::string& field, const std::string& what);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
};

RheometerData read_rheometer_csv(const std::filesystem::path& path);
// Same, from a stream; source_name is what messages call the file.
RheometerData parse_rheometer_csv(std::istream& in, const std::string& source_name);

// The rows as a CSV that read_rheometer_csv reads back (provenance as `#` lines first;
// viscosities in mPa s, written with the digits that read back exactly).
void write_rheometer_csv(const RheometerData& data, std::ostream& out);

}  // namespace rbcal::calibration
