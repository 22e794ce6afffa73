// `rbcal library generate PLAN.json`: runs a sweep plan into a library folder.
// Parallel on one machine with --jobs (one process per job, each taking the next free
// case), across a cluster with `mpirun -np K` or a scheduler array (--case-index):
// workers coordinate only through file locks in the library folder, so any mix of
// them may run at once, and a killed worker's case resumes from its checkpoint.
#include <omp.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/backend_option.hpp"
#include "cli/commands.hpp"
#include "cli/number_validators.hpp"
#include "cli/whole_line_stream.hpp"
#include "solver/sweep/sweep_runner.hpp"

extern char** environ;

namespace rbcal::cli {

namespace {

struct GenerateOptions {
  std::string plan_path;
  std::string library_dir;
  int jobs = 1;
  int threads = 0;
  int case_index = -1;
  bool retry_failed = false;
  bool quiet = false;
  std::string worker;  // set for the processes that --jobs starts
  std::string backend = "cpu";
};

// An MPI rank (OpenMPI, MPICH/Hydra, Slurm) names the worker, and the number of ranks
// scales the sweep's ETA; no MPI calls are needed.
struct LaunchRank {
  std::string name = "worker";
  int ranks = 1;
};

LaunchRank launch_rank() {
  static constexpr std::pair<const char*, const char*> kLaunchers[] = {
      {"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"}, {"PMI_RANK", "PMI_SIZE"}, {"SLURM_PROCID", "SLURM_NTASKS"}};
  LaunchRank r;
  for (const auto& [rank, size] : kLaunchers) {
    if (const char* v = std::getenv(rank)) {
      r.name = std::string("rank ") + v;
      if (const char* n = std::getenv(size)) r.ranks = std::max(1, std::atoi(n));
      break;
    }
  }
  return r;
}

std::vector<pid_t> children;
extern "C" void forward_signal(int sig) {
  for (pid_t c : children) ::kill(c, sig);
}

// Starts `jobs` copies of this command, each a single worker, and waits for them.
int run_jobs(const GenerateOptions& o, int threads) {
  std::vector<std::string> base = {"/proc/self/exe", "library", "generate", o.plan_path, "--library", o.library_dir,
                                   "--threads", std::to_string(threads)};
  if (o.retry_failed) base.push_back("--retry-failed");
  if (o.quiet) base.push_back("--quiet");
  base.insert(base.end(), {"--backend", o.backend});
  struct sigaction sa {};
  sa.sa_handler = forward_signal;
  ::sigaction(SIGTERM, &sa, nullptr);
  ::signal(SIGINT, SIG_IGN);  // Ctrl-C reaches the workers directly (same process group)
  for (int j = 0; j < o.jobs; ++j) {
    std::vector<std::string> args = base;
    args.push_back("--worker-name");
    args.push_back("job " + std::to_string(j + 1) + "/" + std::to_string(o.jobs));
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (::posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ) != 0)
      throw std::runtime_error("cannot start worker process");
    children.push_back(pid);
  }
  int worst = 0;
  for (pid_t c : children) {
    int status = 0;
    ::waitpid(c, &status, 0);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    worst = std::max(worst, code);
  }
  return worst;
}

void run_generate(const GenerateOptions& o) {
  const solver::SweepPlan plan = solver::read_sweep_plan(o.plan_path);
  std::string lib = o.library_dir;
  if (lib.empty()) lib = std::filesystem::path(o.plan_path).stem().string();
  if (o.jobs > 1 && o.worker.empty()) {
    const int cores = omp_get_num_procs();
    const int threads = o.threads > 0 ? o.threads : std::max(1, cores / o.jobs);
    GenerateOptions oo = o;
    oo.library_dir = lib;
    std::cerr << "rbcal library generate: " << plan.cases.size() << " cases into " << lib << "/ with " << o.jobs
              << " worker processes of " << threads << " threads\n";
    const int code = run_jobs(oo, threads);
    if (code != 0) throw std::runtime_error("a worker process ended with status " + std::to_string(code));
    return;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  solver::SweepOptions so;
  so.library_dir = lib;
  so.case_index = o.case_index;
  const LaunchRank rank = launch_rank();
  so.worker = o.worker.empty() ? rank.name : o.worker;
  so.workers = o.worker.empty() ? rank.ranks : std::max(1, o.jobs);
  so.retry_failed = o.retry_failed;
  so.backend = backend_from_option(o.backend);
  WholeLineStream progress(STDERR_FILENO);
  so.progress = o.quiet ? nullptr : &progress;
  const solver::SweepSummary s = solver::run_sweep(plan, so);
  std::cout << "[" << so.worker << "] " << s.finished << " cases finished now, " << s.already_done
            << " before; " << s.claimed_elsewhere << " running elsewhere; " << s.failed << " failed (see " << lib
            << "/failed/)" << (s.interrupted ? "; interrupted, resume by running the same command" : "") << "\n";
  if (s.interrupted) std::exit(130);
  if (s.failed > 0) std::exit(3);
}

}  // namespace

void add_library_generate_command(CLI::App& library) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* cmd = library.add_subcommand(
      "generate",
      "Run a sweep plan (schema rbcal.plan/1) into a library folder; resumable, parallel (--jobs, mpirun, --case-index)");
  cmd->add_option("plan", o->plan_path, "Plan file: grid (or list) of phi, Ca, lambda and a base case (see data/library/)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-l,--library", o->library_dir, "Library folder (default: the plan's file name without .json)");
  cmd->add_option("-j,--jobs", o->jobs, "Worker processes on this machine, each running one case at a time")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--threads", o->threads, "OpenMP threads per worker (default: cores / jobs)")->check(CLI::Range(1, 4096));
  cmd->add_option("--case-index", o->case_index,
                  "Run only this case (0-based, plan order: lambda, then Ca, then phi; a listed plan: its order), e.g. $SLURM_ARRAY_TASK_ID")
      ->check(kNonNegative);
  cmd->add_flag("--retry-failed", o->retry_failed, "Run again the cases a solver guard stopped (listed in LIB/failed/)");
  cmd->add_flag("-q,--quiet", o->quiet, "Only the summary line");
  add_backend_option(cmd, o->backend);
  cmd->add_option("--worker-name", o->worker, "Name in progress lines (set by --jobs for its workers)")->group("");
  cmd->callback([o] { run_generate(*o); });
}

}  // namespace rbcal::cli
