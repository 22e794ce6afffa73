// `rbcal bench`: the fluid update's throughput against a memory-bandwidth roofline
// measured in the same run (STREAM triad), as DESIGN.md section 7 asks.
#include <omp.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/lattice_throughput.hpp"
#include "bench/stream_triad.hpp"
#include "cli/commands.hpp"
#include "rbcal/build_info.hpp"

namespace rbcal::cli {

namespace {

struct BenchOptions {
  std::vector<int> box = {256, 160, 256};  // the seed study's 16a x 10a x 16a at N_a = 16
  int steps = 5;
  int repetitions = 5;
  double triad_mib = 256.0;  // per array; must dwarf the last-level cache
  int threads = 0;
  std::string json_path;
};

std::string host_name() {
  char name[256] = {0};
  return gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : std::string("unknown");
}

void run_bench(const BenchOptions& o) {
  if (o.box.size() != 3 || o.box[0] < 1 || o.box[1] < 1 || o.box[2] < 1)
    throw std::invalid_argument("--box needs three positive node counts nx,ny,nz");
  if (o.steps < 1 || o.repetitions < 1) throw std::invalid_argument("--steps and --repetitions must be >= 1");
  if (!(o.triad_mib > 0.0)) throw std::invalid_argument("--triad-mib must be positive");
  if (o.threads > 0) omp_set_num_threads(o.threads);

  const auto elements = static_cast<std::size_t>(o.triad_mib * 1024.0 * 1024.0 / 8.0);
  const bench::TriadResult triad = bench::measure_stream_triad(elements, o.repetitions);
  const bench::LatticeThroughputResult lbm =
      bench::measure_lattice_throughput({o.box[0], o.box[1], o.box[2]}, o.steps, o.repetitions);

  const double lbm_bytes_per_s = lbm.median_updates_per_s * bench::LatticeThroughputResult::bytes_per_update;
  const double fraction = lbm_bytes_per_s / triad.median_bytes_per_s;
  std::printf("rbcal bench (%s, %s build, %d threads, host %s)\n", build_info::git_revision,
              build_info::build_type, lbm.threads, host_name().c_str());
  std::printf("  STREAM triad       %.1f MiB x 3 arrays, median of %d: %.2f GB/s\n", o.triad_mib,
              o.repetitions, triad.median_bytes_per_s * 1e-9);
  std::printf("  lattice update     %d x %d x %d nodes, D3Q19 TRT + variable viscosity + Guo force\n",
              lbm.box[0], lbm.box[1], lbm.box[2]);
  std::printf("                     median of %d x %d steps: %.2f MLUPS\n", o.repetitions, o.steps,
              lbm.median_updates_per_s * 1e-6);
  std::printf("                     %.0f B/update -> %.2f GB/s\n",
              bench::LatticeThroughputResult::bytes_per_update, lbm_bytes_per_s * 1e-9);
  std::printf("  roofline fraction  %.1f %% of STREAM triad (target >= 60 %%)\n", 100.0 * fraction);

  if (!o.json_path.empty()) {
    nlohmann::json j;
    j["git_revision"] = build_info::git_revision;
    j["host"] = host_name();
    j["threads"] = lbm.threads;
    j["triad"] = {{"array_mib", o.triad_mib}, {"seconds", triad.seconds},
                  {"median_bytes_per_s", triad.median_bytes_per_s}};
    j["lattice"] = {{"box", lbm.box},
                    {"steps_per_repetition", lbm.steps_per_repetition},
                    {"seconds", lbm.seconds},
                    {"median_updates_per_s", lbm.median_updates_per_s},
                    {"bytes_per_update", bench::LatticeThroughputResult::bytes_per_update}};
    j["roofline_fraction"] = fraction;
    std::ofstream out(o.json_path);
    if (!out) throw std::runtime_error("cannot write " + o.json_path);
    out << j.dump(2) << "\n";
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
  cmd->add_option("--steps", opts->steps, "Time steps per timed repetition")->capture_default_str();
  cmd->add_option("--repetitions", opts->repetitions, "Timed repetitions (the median is reported)")
      ->capture_default_str();
  cmd->add_option("--triad-mib", opts->triad_mib, "Size of each STREAM-triad array [MiB]")
      ->capture_default_str();
  cmd->add_option("--threads", opts->threads, "OpenMP threads (default: all cores)");
  cmd->add_option("--json", opts->json_path, "Also write the measurements as JSON to this file");
  cmd->callback([opts] { run_bench(*opts); });
}

}  // namespace rbcal::cli
