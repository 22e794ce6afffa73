#pragma once
// Where the shipped data (samples, reference measurements, the default library) lives:
// found relative to the running executable, so an installed or moved rbcal finds it.
//   1. $RBCAL_DATA, if set (a folder laid out like the repository's data/);
//   2. EXE_DIR/../share/rbcal/data: the installed layout (cmake --install puts the
//      executable in PREFIX/bin and the data in PREFIX/share/rbcal/data), and the build
//      tree's (build/share/rbcal/data is a link to the source tree's data/, made by CMake).
// Throws naming what it tried when neither exists.
#include <filesystem>

namespace rbcal::cli {

std::filesystem::path data_folder();

// data_folder() / relative, as a string for option defaults; if the folder cannot be
// found, a placeholder that names the problem (the command fails only if it is used).
std::string shipped_file(const std::string& relative);

}  // namespace rbcal::cli
