// `rbcal bench`: the fluid update's throughput against a memory-bandwidth roofline
// measured in the same run (STREAM triad), the bar the fluid update is held to.
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/calibration_scaling.hpp"
#include "bench/coupled_step.hpp"
#include "bench/host_description.hpp"
#include "bench/lattice_throughput.hpp"
#include "bench/roofline.hpp"
#include "cli/backend_option.hpp"
#include "cli/commands.hpp"
#include "formats/units.hpp"
#include "formats/json_file.hpp"
#include "formats/provenance.hpp"
#include "rbcal/build_info.hpp"
#include "solver/fluid/fluid_lattice.hpp"
#include "solver/simulation/simulation_case.hpp"
#include "surrogate/offset_family_file.hpp"
#include "cli/data_folder.hpp"

namespace rbcal::cli {

namespace {

struct BenchOptions {
  std::vector<int> box = {256, 160, 256};  // the seed study's 16a x 10a x 16a at N_a = 16
  int steps = 5;
  int rounds = 7;
  double triad_mib = 1024.0;  // per array; must dwarf the last-level cache (some hosts report 320 MiB)
  int threads = 0;
  std::string json_path;
  std::string case_path;  // case mode: time the parts of a coupled step
  int case_steps = 20;
  std::string case_checkpoint;  // case mode: the state to start from
  std::string backend = "cpu";
  std::string precision = "double";
  int prefetch = solver::FluidConfig{}.prefetch_distance;  // fluid mode: populations ahead
  std::vector<int> calibration_points;  // calibration mode: sample sizes
  std::string surrogate;                // its model (default: the shipped one)
  bool no_mcmc = false;
  std::string save_samples;             // calibration mode: write the samples here
};

void run_calibration_bench(const BenchOptions& o) {
  const std::string model_path = o.surrogate.empty() ? shipped_file("library/default/surrogate_family.json") : o.surrogate;
  const std::unique_ptr<surrogate::ViscosityModel> model = surrogate::load_viscosity_model(model_path);
  bench::CalibrationScalingOptions options;
  options.points = o.calibration_points;
  options.mcmc = !o.no_mcmc;
  options.save_folder = o.save_samples;
  if (!o.save_samples.empty()) std::filesystem::create_directories(o.save_samples);
  std::printf("rbcal bench --calibration-points (rbcal %s, %d threads, host %s)\n  %s\n  model %s; samples drawn at G_s 2 uN/m, "
              "5 hematocrits, 40-1000 1/s, 3 %% error, calibrated as rbcal calibrate does; one run each\n",
              build_info::git_revision, omp_get_max_threads(), formats::host_name().c_str(),
              bench::describe_host().line().c_str(), model_path.c_str());
  std::printf("| points | direct [s] | all methods [s] | of which MCMC [s] | MCMC posterior evaluations | G_s direct [uN/m] | G_s MCMC [uN/m] |\n"
              "|---|---|---|---|---|---|---|\n");
  std::fflush(stdout);
  const auto rows = bench::time_calibration_scaling(*model, options, [](const bench::CalibrationScalingRow& r) {
    if (r.all_seconds >= 0.0)
      std::printf("| %d | %.2f | %.1f | %.1f | %lld | %.3f | %.3f |\n", r.points, r.direct_seconds, r.all_seconds,
                  r.mcmc_seconds, r.mcmc_evaluations, r.direct_shear_modulus * kMicro, r.mcmc_shear_modulus * kMicro);
    else
      std::printf("| %d | %.2f | - | - | - | %.3f | - |\n", r.points, r.direct_seconds, r.direct_shear_modulus * kMicro);
    std::fflush(stdout);
  });
  if (!o.json_path.empty()) {
    nlohmann::json j = {{"provenance", formats::provenance_block()}, {"threads", omp_get_max_threads()}, {"model", model_path}};
    for (const auto& r : rows)
      j["rows"].push_back({{"points", r.points}, {"direct_seconds", r.direct_seconds}, {"all_seconds", r.all_seconds},
                           {"mcmc_seconds", r.mcmc_seconds}, {"mcmc_evaluations", r.mcmc_evaluations},
                           {"direct_shear_modulus", r.direct_shear_modulus}, {"mcmc_shear_modulus", r.mcmc_shear_modulus}});
    formats::write_json_atomically(o.json_path, j);
  }
}

void run_case_bench(const BenchOptions& o) {
  const bench::CoupledStepTimings t = bench::time_coupled_step(solver::read_case(o.case_path), o.case_path, o.case_steps,
                                                               backend_from_option(o.backend), o.rounds,
                                                               o.case_checkpoint);
  std::printf("rbcal bench --case %s (rbcal %s, %d threads, host %s)\n  %s\n%s", o.case_path.c_str(),
              build_info::git_revision, omp_get_max_threads(), formats::host_name().c_str(),
              bench::describe_host().line().c_str(), t.brief_report().c_str());
  if (!o.json_path.empty()) {
    nlohmann::json j = {{"case", o.case_path}, {"provenance", formats::provenance_block()}, {"threads", omp_get_max_threads()}};
    j.update(t.to_json());
    formats::write_json_atomically(o.json_path, j);
  }
}

// Rounds whose streaming-store triads differ by more than this are reported as unsteady.
constexpr double kSteadyBandwidthRatio = 1.3;

void run_bench(const BenchOptions& o) {
  if (o.box.size() != 3 || o.box[0] < 1 || o.box[1] < 1 || o.box[2] < 1)
    throw std::invalid_argument("--box needs three positive node counts nx,ny,nz");
  if (o.steps < 1 || o.rounds < 1) throw std::invalid_argument("--steps and --rounds must be >= 1");
  if (!(o.triad_mib > 0.0)) throw std::invalid_argument("--triad-mib must be positive");
  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (!o.calibration_points.empty()) {
    run_calibration_bench(o);
    return;
  }
  if (!o.case_path.empty()) {
    run_case_bench(o);
    return;
  }

  bench::RooflineSettings settings;
  settings.box = {o.box[0], o.box[1], o.box[2]};
  settings.steps = o.steps;
  settings.rounds = o.rounds;
  settings.single_precision = o.precision == "float";
  settings.prefetch_distance = o.prefetch;
  settings.triad_elements = static_cast<std::size_t>(o.triad_mib * 1024.0 * 1024.0 / 8.0);
  const bench::RooflineResult r = bench::measure_roofline(settings);
  const double bytes_per_update = settings.single_precision ? bench::LatticeThroughput::bytes_per_update_single
                                                           : bench::LatticeThroughput::bytes_per_update;

  std::printf("rbcal bench (rbcal %s, %s build, %d threads, host %s)\n", build_info::git_revision,
              build_info::build_type, r.threads, formats::host_name().c_str());
  std::printf("  %s\n", bench::describe_host().line().c_str());
  std::printf("  %d alternating rounds; medians over rounds\n", o.rounds);
  std::printf("  STREAM triad (3 x %.0f MiB)      %8.2f GB/s  ordinary stores, 24 B/element counted\n",
              o.triad_mib, r.median_triad * 1e-9);
  const auto [slowest, fastest] =
      std::minmax_element(r.triad_streaming_bytes_per_s.begin(), r.triad_streaming_bytes_per_s.end());
  std::printf("  STREAM triad, streaming stores  %8.2f GB/s  rounds %.1f-%.1f GB/s\n", r.median_triad_streaming * 1e-9,
              *slowest * 1e-9, *fastest * 1e-9);
  std::printf("  lattice update                  %8.2f MLUPS %d x %d x %d, D3Q19 TRT, variable viscosity, Guo force, %s populations\n",
              r.median_updates * 1e-6, o.box[0], o.box[1], o.box[2], o.precision.c_str());
  std::printf("                                            prefetch %d populations ahead%s\n", o.prefetch,
              o.prefetch == 0 ? " (none)" : "");
  std::printf("                                  %8.2f GB/s  at %.0f B/update\n",
              r.median_updates * bytes_per_update * 1e-9, bytes_per_update);
  const long l3 = sysconf(_SC_LEVEL3_CACHE_SIZE);
  if (l3 > 0 && 3.0 * o.triad_mib * 1024 * 1024 < 4.0 * l3)
    std::printf("  warning: the triad arrays are not much larger than the %.0f MiB last-level cache;\n"
                "           the roofline is the cache's, not memory's (raise --triad-mib)\n",
                l3 / 1048576.0);
  std::printf("  huge pages         %.2f of %.2f GiB of the process's anonymous memory (%.0f %%)\n",
              r.huge_page_bytes / 1073741824.0, r.anonymous_bytes / 1073741824.0,
              r.anonymous_bytes > 0 ? 100.0 * r.huge_page_bytes / r.anonymous_bytes : 0.0);
  std::printf("  roofline fraction  %.1f %% of STREAM triad (target >= 60 %%), %.1f %% of the streaming-store triad\n",
              100.0 * r.fraction_of_triad, 100.0 * r.fraction_of_streaming_triad);
  // Some shared hosts' memory bandwidth swings between rounds (one went from 18 to 74 GB/s
  // within a run); then one run's fraction is a loose figure.
  if (*fastest > kSteadyBandwidthRatio * *slowest)
    std::printf("  warning: the streaming-store triad varied %.1fx between rounds (this host's memory bandwidth is\n"
                "           not steady): compare the fractions of several runs, or more --rounds\n",
                *fastest / *slowest);

  if (!o.json_path.empty()) {
    nlohmann::json j;
    j["provenance"] = formats::provenance_block();
    j["threads"] = r.threads;
    j["box"] = o.box;
    j["steps_per_round"] = o.steps;
    j["triad_array_mib"] = o.triad_mib;
    j["triad_bytes_per_s"] = r.triad_bytes_per_s;
    j["triad_streaming_bytes_per_s"] = r.triad_streaming_bytes_per_s;
    j["lattice_updates_per_s"] = r.lattice_updates_per_s;
    j["bytes_per_update"] = bytes_per_update;
    j["precision"] = o.precision;
    j["prefetch_distance"] = o.prefetch;
    const bench::HostDescription host = bench::describe_host();
    j["cpu_model"] = host.cpu_model;
    j["cpu_signature"] = host.cpu_signature;
    j["anonymous_bytes"] = r.anonymous_bytes;
    j["huge_page_bytes"] = r.huge_page_bytes;
    j["vector_doubles"] = host.vector_doubles;
    j["transparent_huge_pages"] = host.huge_pages;
    j["page_bytes"] = host.page_bytes;
    j["roofline_fraction"] = r.fraction_of_triad;
    j["roofline_fraction_streaming_triad"] = r.fraction_of_streaming_triad;
    formats::write_json_atomically(o.json_path, j);
  }
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto opts = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench", "Fluid-update throughput (MLUPS) and its fraction of the STREAM-triad bandwidth roofline");
  cmd->add_option("--box", opts->box, "Lattice nodes nx ny nz (default: paper box at N_a = 16)")
      ->expected(3)
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--steps", opts->steps, "Lattice time steps per round")->capture_default_str();
  cmd->add_option("--rounds", opts->rounds, "Alternating rounds (medians are reported): triad and lattice, or with --case coupled and plain fluid steps")
      ->capture_default_str();
  cmd->add_option("--triad-mib", opts->triad_mib, "Size of each STREAM-triad array [MiB]")
      ->capture_default_str();
  cmd->add_option("--threads", opts->threads, "OpenMP threads (default: all cores)");
  cmd->add_option("--json", opts->json_path, "Also write the measurements as JSON to this file");
  cmd->add_option("--case", opts->case_path,
                  "Case mode: time fluid, membrane, spreading, indicator and interpolation for this case file")
      ->check(CLI::ExistingFile);
  cmd->add_option("--case-steps", opts->case_steps, "Case mode: timed steps (after 2 warm-up steps)")
      ->capture_default_str();
  cmd->add_option("--case-checkpoint", opts->case_checkpoint,
                  "Case mode: start from this checkpoint of the case (written by rbcal simulate CASE --max-steps N): "
                  "the cells where a run has carried them, most of them sheared out of the box in x")
      ->check(CLI::ExistingFile);
  cmd->add_option("--calibration-points", opts->calibration_points,
                  "Calibration mode: time rbcal calibrate (direct, then all methods) on samples of these sizes, e.g. 28,100,500,2000,10000")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cmd->add_option("--surrogate", opts->surrogate, "Calibration mode: the model (default: the shipped surrogate family)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--save-samples", opts->save_samples,
                  "Calibration mode: also write each sample to this folder as scaling_N.csv (to time rbcal calibrate on it)");
  cmd->add_flag("--no-mcmc", opts->no_mcmc, "Calibration mode: time the direct method only");
  add_backend_option(cmd, opts->backend);
  cmd->add_option("--precision", opts->precision,
                  "Population storage of the lattice update: double, or float (32 bits, shifted; numerics.precision)")
      ->check(CLI::IsMember({"double", "float"}))
      ->capture_default_str();
  cmd->add_option("--prefetch", opts->prefetch,
                  "Fluid mode: how far ahead every read stream of the update is prefetched, in populations "
                  "(0: none); to find a host's best distance (the results do not depend on it)")
      ->check(CLI::IsMember(std::vector<int>(solver::kPrefetchDistances.begin(), solver::kPrefetchDistances.end())))
      ->capture_default_str();
  cmd->callback([opts] {
    if (opts->backend == "device" && opts->case_path.empty())
      throw CLI::ValidationError("--backend device", "times a case: give --case FILE");
    if (!opts->case_checkpoint.empty() && opts->case_path.empty())
      throw CLI::ValidationError("--case-checkpoint", "is a state of a case: give its --case FILE too");
    run_bench(*opts);
  });
}

}  // namespace rbcal::cli
