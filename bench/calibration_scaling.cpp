#include "bench/calibration_scaling.hpp"

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>
#include <filesystem>

#include "calibration/calibration_job.hpp"
#include "calibration/capillary_number.hpp"
#include "calibration/model_setup.hpp"
#include "calibration/rheometer_data.hpp"
#include "formats/json_file.hpp"

namespace rbcal::bench {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// n points over five hematocrits, each a log-spaced sweep of 40-1000 1/s, drawn from the model
// at its nuisances' means with 3 % measurement error; eta0 known (1.2 mPa s).
calibration::SampleData sample_of(const surrogate::ViscosityModel& model, int n, double shear_modulus,
                                  std::mt19937_64& rng) {
  const double hematocrits[] = {0.25, 0.325, 0.40, 0.475, 0.55};
  const double plasma_viscosity = 1.2e-3, relative_sd = 0.03;
  std::normal_distribution<double> normal;
  calibration::SampleData sample;
  sample.name = "scaling_" + std::to_string(n);
  sample.plasma.eta0 = plasma_viscosity;
  for (int line = 0; line < 5; ++line) {
    const int count = n / 5 + (line < n % 5 ? 1 : 0);
    for (int i = 0; i < count; ++i) {
      calibration::RelativeViscosityPoint p;
      p.phi = hematocrits[line];
      p.shear_rate = 40.0 * std::pow(25.0, count > 1 ? i / (count - 1.0) : 0.5);
      const double ca = calibration::capillary_number(plasma_viscosity, p.shear_rate, calibration::kDefaultCellRadius,
                                                      shear_modulus);
      const double eta_re = model.predict(p.phi, ca, calibration::kDefaultViscosityRatio).eta_re;
      p.eta_re_sd = relative_sd * eta_re;
      p.eta_re = eta_re + p.eta_re_sd * normal(rng);
      sample.points.push_back(p);
    }
  }
  return sample;
}

}  // namespace

std::string scaling_sample_csv(const calibration::SampleData& sample) {
  std::ostringstream out;
  out.precision(10);
  out << "# " << sample.name << ": drawn by rbcal bench --calibration-points from its model (see the bench's output)\n"
      << "sample,kind,phi,shear_rate_per_s,viscosity_mPa_s,sd_mPa_s,n\n";
  const double eta0_mpa_s = sample.plasma.eta0 * 1e3;
  for (const double shear_rate : {100.0, 300.0, 1000.0})
    out << sample.name << ",plasma,0," << shear_rate << ',' << eta0_mpa_s << ',' << 0.01 * eta0_mpa_s << ",10\n";
  for (const auto& p : sample.points)
    out << sample.name << ",suspension," << p.phi << ',' << p.shear_rate << ',' << p.eta_re * eta0_mpa_s << ','
        << p.eta_re_sd * eta0_mpa_s << ",1\n";
  return out.str();
}

std::vector<CalibrationScalingRow> time_calibration_scaling(const surrogate::ViscosityModel& model,
                                                            const CalibrationScalingOptions& options,
                                                            void (*progress)(const CalibrationScalingRow&)) {
  std::vector<CalibrationScalingRow> rows;
  for (const int n : options.points) {
    std::mt19937_64 rng(options.seed + static_cast<std::uint64_t>(n));
    const calibration::SampleData drawn = sample_of(model, n, options.shear_modulus, rng);
    // Through the CSV, as rbcal calibrate reads it (eta0 from the plasma rows, with its error).
    const std::string csv = scaling_sample_csv(drawn);
    if (!options.save_folder.empty())
      formats::write_file_atomically(std::filesystem::path(options.save_folder) / (drawn.name + ".csv"), csv);
    std::istringstream stream(csv);
    const calibration::CalibrationInput input =
        calibration::make_calibration_input(calibration::parse_rheometer_csv(stream, drawn.name + ".csv"));
    calibration::CalibrationJobOptions job;  // rbcal calibrate's defaults
    std::ostringstream log;
    CalibrationScalingRow row;
    row.points = n;
    job.method = "direct";
    auto t = std::chrono::steady_clock::now();
    const calibration::CalibrationReport direct = calibration::calibrate_samples(input, model, job, log);
    row.direct_seconds = seconds_since(t);
    if (direct.samples.front().direct) row.direct_shear_modulus = direct.samples.front().direct->shear_modulus;
    if (options.mcmc) {
      job.method = "all";
      t = std::chrono::steady_clock::now();
      const calibration::CalibrationReport all = calibration::calibrate_samples(input, model, job, log);
      row.all_seconds = seconds_since(t);
      const calibration::SampleReport& r = all.samples.front();
      if (r.mcmc) {
        row.mcmc_shear_modulus = r.mcmc->shear_modulus_median;
        row.mcmc_evaluations = r.mcmc->mcmc.evaluations;
        row.mcmc_seconds = r.mcmc->mcmc.seconds;
      }
    }
    rows.push_back(row);
    if (progress) progress(row);
  }
  return rows;
}

}  // namespace rbcal::bench
