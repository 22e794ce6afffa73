// rbcal: red blood cell deformability from rheometer curves. Thin front end over the
// solver, surrogate and calibration libraries.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "rbcal/build_info.hpp"

int main(int argc, char** argv) {
  CLI::App app{"rbcal: membrane shear elasticity G_s of red blood cells from rheometer curves"};
  app.set_version_flag("--version", std::string("rbcal ") + rbcal::build_info::version + " (" +
                                        rbcal::build_info::git_revision + ")");
  app.require_subcommand(1);
  rbcal::cli::add_couette_command(app);
  rbcal::cli::add_bench_command(app);
  rbcal::cli::add_stretch_command(app);
  rbcal::cli::add_simulate_command(app);
  rbcal::cli::add_overlaps_command(app);
  rbcal::cli::add_surrogate_command(app);
  rbcal::cli::add_calibrate_command(app);
  rbcal::cli::add_model_command(app);
  rbcal::cli::add_recover_command(app);
  CLI::App* library = app.add_subcommand("library", "Simulation libraries: generate, show, propose, extrapolate, effective-phi");
  library->require_subcommand(1);
  rbcal::cli::add_library_generate_command(*library);
  rbcal::cli::add_library_extrapolate_command(*library);
  rbcal::cli::add_library_effective_phi_command(*library);
  rbcal::cli::add_library_inspect_commands(*library);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const rbcal::cli::ExitStatus& e) {
    return e.code;
  } catch (const std::exception& e) {
    std::cerr << "rbcal: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
