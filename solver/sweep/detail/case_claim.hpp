#pragma once
// An exclusive claim on one case of a sweep, held as an advisory lock (flock) on a
// lock file. The kernel drops the lock when its holder exits for any reason, SIGKILL
// included, so a killed worker never leaves a case blocked. Works across processes on
// one machine and across nodes on file systems with flock support (NFSv4, Lustre
// mounted with -o flock).
#include <string>

namespace rbcal::solver {

class CaseClaim {
 public:
  // Tries to take the lock without waiting; held() says whether it succeeded.
  explicit CaseClaim(const std::string& lock_path);
  ~CaseClaim();
  CaseClaim(const CaseClaim&) = delete;
  CaseClaim& operator=(const CaseClaim&) = delete;

  bool held() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace rbcal::solver
