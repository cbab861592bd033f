#pragma once

// A file the command line writes (a picture, a marked mesh) appears whole or not at all:
// the bytes go to a temporary file next to the destination, which is renamed over it only
// once the file system has accepted every byte. The temporary file is created first, so
// an unwritable destination is reported before any long work.

#include <stdexcept>
#include <string>
#include <string_view>

namespace exactgeo::cli {

/// Why an output file could not be written; what() names the file.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputFile {
 public:
  /// Creates the temporary file; throws OutputFileError naming `path` if it cannot.
  explicit OutputFile(std::string path);
  /// Removes the temporary file unless commit() succeeded.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Writes `bytes` and renames the file to the destination. Throws OutputFileError
  /// naming the destination if the file system refuses (the destination is then left as
  /// it was). Once only.
  void commit(std::string_view bytes);

  const std::string& path() const noexcept { return path_; }

 private:
  [[noreturn]] void fail(const std::string& why);

  std::string path_;
  std::string temporary_;
  int fd_ = -1;
};

}  // namespace exactgeo::cli
