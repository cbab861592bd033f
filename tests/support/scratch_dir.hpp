#pragma once

// A fresh directory for one test's files, removed when it goes out of scope (after a
// failed assertion too). Named by the test's prefix and the process, so tests running in
// parallel processes do not share one.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace exactgeo::testing {

struct ScratchDir {
  std::filesystem::path path;

  explicit ScratchDir(const std::string& prefix)
      : path(std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

}  // namespace exactgeo::testing
