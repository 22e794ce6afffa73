// A scratch file name in the temp folder that belongs to the running test alone.
// ctest runs the discovered tests as parallel processes, so two tests that wrote to one
// fixed name could read each other's files (a checkpoint test failed that way in CI).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace rbcal::testing_support {

// temp/rbcal_<suite>_<test>_<stem>; the parameter index of a parameterised test is part
// of the test's name, so each instance gets its own path.
inline std::filesystem::path scratch_path(const std::string& stem) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string("rbcal_") + info->test_suite_name() + "_" + info->name() + "_" + stem;
  std::replace(name.begin(), name.end(), '/', '_');
  return std::filesystem::temp_directory_path() / name;
}

}  // namespace rbcal::testing_support
