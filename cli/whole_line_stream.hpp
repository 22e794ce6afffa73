#pragma once
// An output stream whose lines each leave in one write(2). Workers of one sweep (--jobs
// processes, MPI ranks) share a terminal; std::cerr writes every `<<` on its own, so their
// progress lines would interleave mid-line.
#include <unistd.h>

#include <cerrno>
#include <ostream>
#include <streambuf>
#include <string>

namespace rbcal::cli {

class WholeLineBuffer : public std::streambuf {
 public:
  explicit WholeLineBuffer(int fd) : fd_(fd) {}
  ~WholeLineBuffer() override { emit(); }

 protected:
  int_type overflow(int_type ch) override {
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    line_.push_back(traits_type::to_char_type(ch));
    if (ch == '\n') emit();
    return ch;
  }
  int sync() override {
    emit();
    return 0;
  }

 private:
  void emit() {
    std::size_t done = 0;
    while (done < line_.size()) {
      const ssize_t n = ::write(fd_, line_.data() + done, line_.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;  // progress is best effort: a closed terminal must not stop a sweep
      done += static_cast<std::size_t>(n);
    }
    line_.clear();
  }

  int fd_;
  std::string line_;
};

class WholeLineStream : public std::ostream {
 public:
  explicit WholeLineStream(int fd) : std::ostream(nullptr), buffer_(fd) { rdbuf(&buffer_); }

 private:
  WholeLineBuffer buffer_;
};

}  // namespace rbcal::cli
