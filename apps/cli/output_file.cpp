#include "cli/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace exactgeo::cli {

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  // A name of our own next to the destination (the rename must stay on its file system):
  // O_EXCL refuses an existing file, so a few numbered names are tried. Mode 0666 minus
  // the umask, the mode a plain new file gets.
  const std::string base = path_ + "." + std::to_string(::getpid()) + ".tmp";
  for (int attempt = 0; attempt < 16 && fd_ < 0; ++attempt) {
    temporary_ = attempt == 0 ? base : base + std::to_string(attempt);
    fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const int error = errno;
    temporary_.clear();
    throw OutputFileError("cannot write '" + path_ + "': " + std::strerror(error));
  }
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void OutputFile::fail(const std::string& why) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
  throw OutputFileError("cannot write '" + path_ + "': " + why);
}

void OutputFile::commit(std::string_view bytes) {
  if (fd_ < 0) fail("the file was already written");
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd_, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail(std::strerror(written < 0 ? errno : ENOSPC));
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
  // A full disk or a network file system may report a failure only at the close.
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) fail(std::strerror(errno));
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) fail(std::strerror(errno));
  temporary_.clear();
}

}  // namespace exactgeo::cli
