#pragma once
// The one exception for a file that could not be written: a failure of the machine (a full
// disk, a folder gone read-only), not of the input or of a computation. Its message names the
// file and the system's reason. A sweep stops on it instead of filing the case as failed, so
// that the case runs again once the disk has room.
#include <stdexcept>
#include <string>

namespace rbcal::formats {

class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rbcal::formats
