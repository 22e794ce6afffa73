// A checkpoint carries a checksum: any overwritten byte is refused when read, naming the
// file, where before four overwritten bytes resumed into a different result; an intact
// file reads back exactly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "solver/simulation/checkpoint.hpp"
#include "../scratch_path.hpp"

using namespace rbcal::solver;

namespace {

CheckpointState small_state() {
  CheckpointState s;
  s.case_json = R"({"schema":"rbcal.case/1"})";
  s.steps = 1234;
  for (int i = 0; i < 1001; ++i) s.populations.push_back(0.01 * i);
  s.positions = {{Vec3(1, 2, 3), Vec3(4, 5, 6)}, {Vec3(7, 8, 9)}};
  s.velocities = {{Vec3(0.1, 0.2, 0.3), Vec3(0.4, 0.5, 0.6)}, {Vec3(0.7, 0.8, 0.9)}};
  s.forces = s.velocities;
  s.velocity_sum = {1.5, 2.5, 3.5};
  s.velocity_sum_steps = 1;
  return s;
}

void overwrite(const std::filesystem::path& p, std::streamoff at, const char* bytes, std::size_t n) {
  std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(at);
  f.write(bytes, static_cast<std::streamsize>(n));
}

}  // namespace

TEST(CheckpointChecksum, IntactFileReadsBackExactly) {
  const auto path = rbcal::testing_support::scratch_path("intact.bin");
  write_checkpoint(path.string(), small_state());
  const CheckpointState back = read_checkpoint(path.string());
  EXPECT_EQ(back.steps, 1234);
  EXPECT_EQ(back.populations, small_state().populations);
  EXPECT_EQ(back.velocity_sum, small_state().velocity_sum);
  std::filesystem::remove(path);
}

TEST(CheckpointChecksum, DamagedBytesAreRefusedNamingTheFile) {
  const auto path = rbcal::testing_support::scratch_path("damaged.bin");
  const auto size = [&] {
    write_checkpoint(path.string(), small_state());
    return static_cast<std::streamoff>(std::filesystem::file_size(path));
  };
  // Four bytes inside the populations (a plausible value, so only the checksum can tell),
  // in the case text, in the step count, and in the last cell's forces.
  for (const std::streamoff at : {std::streamoff{200}, std::streamoff{20}, std::streamoff{8 + 8 + 26 + 2},
                                  size() - 8 - 8 - 8 * 3 - 16 - 40}) {
    size();
    overwrite(path, at, "\x12\x34\x56\x78", 4);
    try {
      read_checkpoint(path.string());
      FAIL() << "a checkpoint damaged at byte " << at << " was read";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_TRUE(what.find("damaged") != std::string::npos || what.find("implausible") != std::string::npos ||
                  what.find("truncated") != std::string::npos)
          << what;
    }
  }
  std::filesystem::remove(path);
}
