#pragma once
// Registration of the `rbcal` sub-commands; each lives in its own file.
#include <CLI/CLI.hpp>

namespace rbcal::cli {

// Thrown by a command that has said what it had to and must end with this exit status
// (e.g. 130 after SIGINT, as shells expect); main returns it.
struct ExitStatus {
  int code = 1;
};

void add_couette_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_stretch_command(CLI::App& app);
void add_simulate_command(CLI::App& app);
void add_overlaps_command(CLI::App& app);
void add_surrogate_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_model_command(CLI::App& app);
void add_recover_command(CLI::App& app);
// `show` and `propose` under the `library` sub-command (created in main.cpp).
void add_library_inspect_commands(CLI::App& library);
// `generate` under the `library` sub-command.
void add_library_generate_command(CLI::App& library);
// `extrapolate` under the `library` sub-command.
void add_library_extrapolate_command(CLI::App& library);
// `effective-phi` under the `library` sub-command.
void add_library_effective_phi_command(CLI::App& library);

}  // namespace rbcal::cli
