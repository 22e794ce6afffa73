#include "solver/sweep/detail/case_claim.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace rbcal::solver {

CaseClaim::CaseClaim(const std::string& lock_path) {
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open lock file " + lock_path + ": " + std::strerror(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    if (err == EWOULDBLOCK) return;  // another worker has it
    throw std::runtime_error("cannot lock " + lock_path + ": " + std::strerror(err));
  }
  fd_ = fd;
}

CaseClaim::~CaseClaim() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace rbcal::solver
