#pragma once
// --backend cpu|device for the commands that step the solver (simulate, bench).
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

#include "solver/device/device_stepper.hpp"

namespace rbcal::cli {

inline void add_backend_option(CLI::App* cmd, std::string& backend) {
  cmd->add_option("--backend", backend,
                  "cpu: the tuned CPU solver; device: every step on the device path, on the GPU in a build with "
                  "-DRBCAL_CUDA=ON (this build: " + std::string(solver::device_is_gpu() ? "GPU" : "host threads, for tests") +
                      ")")
      ->check(CLI::IsMember({"cpu", "device"}))
      ->default_str("cpu");
}

inline solver::Backend backend_from_option(const std::string& backend) {
  if (backend != "device") return solver::Backend::Cpu;
  if (!solver::device_is_gpu())
    std::cerr << "note: this rbcal was built without CUDA: the device path runs on the host's threads, slower than "
                 "--backend cpu (build with -DRBCAL_CUDA=ON for a GPU)\n";
  return solver::Backend::Device;
}

}  // namespace rbcal::cli
