#include "calibration/rheometer_data.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <ostream>
#include <map>
#include <sstream>
#include <tuple>

#include "formats/units.hpp"

namespace rbcal::calibration {

namespace {

constexpr std::array<const char*, 7> kColumns = {"sample", "kind", "phi", "shear_rate_per_s",
                                                 "viscosity_mPa_s", "sd_mPa_s", "n"};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

struct LineReader {
  const std::string& file;
  int line;
  const std::vector<std::string>& fields;
  const std::array<int, kColumns.size()>& column_of;

  const std::string& text(int column) const { return fields[column_of[column]]; }

  [[noreturn]] void fail(int column, const std::string& what) const {
    throw RheometerDataError(file, line, kColumns[column], what);
  }

  double number(int column) const {
    const std::string& s = text(column);
    if (s.empty()) fail(column, "empty, expected a number");
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(value))
      fail(column, "'" + s + "' is not a finite number");
    return value;
  }
};

}  // namespace

RheometerDataError::RheometerDataError(const std::string& file, int line, const std::string& field,
                                       const std::string& what)
    : std::runtime_error(file + ":" + std::to_string(line) + ": field " + field + ": " + what),
      file_(file),
      line_(line),
      field_(field) {}

std::vector<std::string> RheometerData::sample_names() const {
  std::vector<std::string> names;
  for (const auto& row : rows)
    if (std::find(names.begin(), names.end(), row.sample) == names.end()) names.push_back(row.sample);
  return names;
}

RheometerData read_rheometer_csv(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw RheometerDataError(path.string(), 0, "(file)", "is a folder, not a CSV file");
  std::ifstream in(path);
  if (!in) throw RheometerDataError(path.string(), 0, "(file)", std::string("cannot open for reading: ") + std::strerror(errno));
  return parse_rheometer_csv(in, path.string());
}

RheometerData parse_rheometer_csv(std::istream& in, const std::string& source_name) {
  enum Column { kSample, kKind, kPhi, kShearRate, kViscosity, kSd, kRepeats };
  RheometerData data;
  data.source = source_name;
  std::array<int, kColumns.size()> column_of{};
  std::size_t header_width = 0;
  bool have_header = false;
  // (sample, kind, phi, shear rate) -> line, for duplicates.
  std::map<std::tuple<std::string, int, double, double>, int> seen;
  std::map<std::string, std::pair<int, bool>> first_line_and_plasma;
  std::map<std::string, MeasurementKind> plasma_kind;  // per sample: measured or assumed

  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    // Excel's "CSV UTF-8" starts the file with a byte-order mark; it is not part of the header.
    if (line == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.erase(0, 3);
    const std::string text = trim(raw);
    if (text.empty()) continue;
    if (text.front() == '#') {
      data.provenance.push_back(trim(text.substr(1)));
      continue;
    }
    const std::vector<std::string> fields = split_fields(text);
    if (!have_header) {
      header_width = fields.size();
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        const auto it = std::find(fields.begin(), fields.end(), kColumns[c]);
        if (it == fields.end())
          throw RheometerDataError(source_name, line, kColumns[c], "missing from the header");
        column_of[c] = static_cast<int>(it - fields.begin());
      }
      for (const auto& name : fields)
        if (std::find_if(kColumns.begin(), kColumns.end(), [&](const char* c) { return name == c; }) ==
            kColumns.end())
          throw RheometerDataError(source_name, line, name.empty() ? "(empty)" : name,
                                   "unknown column in the header");
      have_header = true;
      continue;
    }
    if (fields.size() != header_width)
      throw RheometerDataError(source_name, line, "(row)",
                               "expected " + std::to_string(header_width) + " fields, found " +
                                   std::to_string(fields.size()));
    const LineReader reader{source_name, line, fields, column_of};
    RheometerRow row;
    row.line = line;
    row.sample = reader.text(kSample);
    if (row.sample.empty()) reader.fail(kSample, "empty sample name");
    const std::string& kind = reader.text(kKind);
    if (kind == "plasma")
      row.kind = MeasurementKind::plasma;
    else if (kind == "suspension")
      row.kind = MeasurementKind::suspension;
    else if (kind == "plasma_assumed")
      row.kind = MeasurementKind::plasma_assumed;
    else
      reader.fail(kKind, "unknown kind '" + kind + "' (expected plasma, suspension or plasma_assumed)");
    const bool assumed = row.kind == MeasurementKind::plasma_assumed;
    row.phi = reader.number(kPhi);
    if (row.kind != MeasurementKind::suspension && row.phi != 0.0)
      reader.fail(kPhi, "plasma rows must have phi = 0");
    if (row.kind == MeasurementKind::suspension && !(row.phi > 0.0 && row.phi < 1.0))
      reader.fail(kPhi, "volume fraction of a suspension must lie in (0, 1)");
    row.shear_rate = reader.number(kShearRate);
    if (assumed && row.shear_rate != 0.0)
      reader.fail(kShearRate, "a plasma_assumed row has no shear rate: write 0");
    if (!assumed && !(row.shear_rate > 0.0)) reader.fail(kShearRate, "shear rate must be positive");
    row.viscosity = reader.number(kViscosity) / kMilli;
    if (!(row.viscosity > 0.0)) reader.fail(kViscosity, "viscosity must be positive");
    row.viscosity_sd = reader.number(kSd) / kMilli;
    if (row.viscosity_sd < 0.0) reader.fail(kSd, "standard deviation must not be negative");
    if (assumed && !(row.viscosity_sd > 0.0))
      reader.fail(kSd, "an assumed plasma viscosity needs its standard deviation (> 0)");
    const double repeats = reader.number(kRepeats);
    if (repeats != std::floor(repeats) || repeats < 1.0 || repeats > 1e9)
      reader.fail(kRepeats, "number of repeats must be an integer >= 1");
    row.repeats = static_cast<int>(repeats);

    auto& sample_state = first_line_and_plasma.try_emplace(row.sample, line, false).first->second;
    if (row.kind != MeasurementKind::suspension) {
      // Measured and assumed plasma rows do not mix, and one assumption is enough.
      const auto [it, first] = plasma_kind.try_emplace(row.sample, row.kind);
      if (!first && (it->second != row.kind || assumed))
        reader.fail(kKind, "sample '" + row.sample + "' already has " +
                               (it->second == MeasurementKind::plasma ? "measured plasma rows"
                                                                      : "a plasma_assumed row") +
                               "; give measured plasma rows or one plasma_assumed row");
      sample_state.second = true;
    }
    const auto key = std::make_tuple(row.sample, static_cast<int>(row.kind), row.phi, row.shear_rate);
    if (const auto it = seen.find(key); it != seen.end())
      reader.fail(kShearRate, "duplicate of line " + std::to_string(it->second) +
                                  " (same sample, kind, phi and shear rate)");
    seen.emplace(key, line);
    data.rows.push_back(row);
  }
  if (!have_header) throw RheometerDataError(source_name, line, "(header)", "no header line");
  if (data.rows.empty()) throw RheometerDataError(source_name, line, "(row)", "no data rows");
  for (const auto& name : data.sample_names()) {
    const auto& [first_line, has_plasma] = first_line_and_plasma.at(name);
    if (!has_plasma)
      throw RheometerDataError(source_name, first_line, "sample",
                               "sample '" + name + "' has no plasma rows (needed for eta0; give measured plasma "
                               "rows or one plasma_assumed row with the assumed eta0 and its sd)");
  }
  return data;
}

void write_rheometer_csv(const RheometerData& data, std::ostream& out) {
  for (const auto& line : data.provenance) out << "# " << line << '\n';
  for (std::size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << kColumns[c];
  // Enough digits that the values read back exactly; the stream's own precision is restored.
  const std::streamsize precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << '\n';
  for (const auto& row : data.rows) {
    const char* kind = row.kind == MeasurementKind::plasma           ? "plasma"
                       : row.kind == MeasurementKind::plasma_assumed ? "plasma_assumed"
                                                                     : "suspension";
    out << row.sample << ',' << kind << ',' << row.phi << ',' << row.shear_rate << ','
        << row.viscosity * kMilli << ',' << row.viscosity_sd * kMilli << ','
        << row.repeats << '\n';
  }
  out.precision(precision);
}

}  // namespace rbcal::calibration
