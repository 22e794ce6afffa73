// `rbcal library generate` killed with SIGKILL at arbitrary moments and started again
// finishes every case exactly once, leaves no half-written file, and gives the same
// results, bit for bit, as a sweep that was never interrupted.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "tests/simulation/same_run.hpp"

extern char** environ;

namespace fs = std::filesystem;
using rbcal::solver::test_cases::slurp;

namespace {

const std::string plan = std::string(RBCAL_TEST_DATA) + "/kill_plan.json";
const std::vector<std::string> ids = {"phi0.05_Ca0.1_lambda3", "phi0.05_Ca0.2_lambda3", "phi0.05_Ca0.4_lambda3"};

pid_t start_generate(const fs::path& lib) {
  std::vector<std::string> args = {RBCAL_EXE, "library", "generate", plan, "--library", lib.string(),
                                   "--threads", "1", "--quiet"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (::posix_spawn(&pid, RBCAL_EXE, nullptr, nullptr, argv.data(), environ) != 0) return -1;
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

int count_finished(const fs::path& lib) {
  int n = 0;
  for (const auto& id : ids) n += fs::exists(lib / "cases" / (id + ".json")) ? 1 : 0;
  return n;
}

bool any_checkpoint(const fs::path& lib) {
  for (const auto& id : ids)
    if (fs::exists(lib / "work" / id / "checkpoint.bin")) return true;
  return false;
}

// Starts a sweep and kills it (SIGKILL) once `ready` holds, or fails after a minute.
template <class Ready>
void kill_when(const fs::path& lib, Ready ready) {
  const pid_t pid = start_generate(lib);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!ready() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(pid, SIGKILL);
  wait_for(pid);
}

}  // namespace

TEST(LibraryGenerate, KilledSweepFinishesEveryCaseOnceWithStraightResults) {
  const fs::path root = fs::temp_directory_path() / ("rbcal_sweep_test_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path straight = root / "straight", killed = root / "killed";

  ASSERT_EQ(wait_for(start_generate(straight)), 0);
  ASSERT_EQ(count_finished(straight), 3);

  // First kill: in the middle of the first case, after a checkpoint.
  kill_when(killed, [&] { return any_checkpoint(killed); });
  EXPECT_LT(count_finished(killed), 3) << "the sweep ended before it could be killed";
  // Second kill: right after a case was published, while the next one runs.
  const int before = count_finished(killed);
  kill_when(killed, [&] { return count_finished(killed) > before; });
  // Third kill: immediately after start.
  kill_when(killed, [] { return true; });
  ASSERT_EQ(wait_for(start_generate(killed)), 0);

  // Exactly the plan's cases, each once, nothing half-written, nothing left in work/.
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(killed / "cases")) files.insert(e.path().filename().string());
  std::set<std::string> expected;
  for (const auto& id : ids) expected.insert({id + ".json", id + ".csv"});
  EXPECT_EQ(files, expected);
  for (const auto& e : fs::directory_iterator(killed / "work")) ADD_FAILURE() << "left in work/: " << e.path();

  for (const auto& id : ids) {
    const auto a = nlohmann::json::parse(slurp(straight / "cases" / (id + ".json")));
    const auto b = nlohmann::json::parse(slurp(killed / "cases" / (id + ".json")));
    EXPECT_EQ(a["result"]["eta_re"].get<double>(), b["result"]["eta_re"].get<double>()) << id;
    EXPECT_EQ(a["result"]["eta_re_wall"].get<double>(), b["result"]["eta_re_wall"].get<double>()) << id;
    EXPECT_EQ(slurp(straight / "cases" / (id + ".csv")), slurp(killed / "cases" / (id + ".csv"))) << id;
  }

  // A finished library is left alone by another run.
  const auto stamp = fs::last_write_time(killed / "cases" / (ids[0] + ".json"));
  ASSERT_EQ(wait_for(start_generate(killed)), 0);
  EXPECT_EQ(stamp, fs::last_write_time(killed / "cases" / (ids[0] + ".json")));
  fs::remove_all(root);
}
