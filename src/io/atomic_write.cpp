#include "vrreg/io/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "vrreg/io/file_error.hpp"

namespace vrreg::io {
namespace {

std::string error_text(int error) { return std::strerror(error); }

// A temporary name beside `path` that no other writer (thread or process) picks at once.
std::string temporary_name(const std::string& path, int attempt) {
  static std::atomic<unsigned> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++) + "." +
         std::to_string(now % 1000000) + "." + std::to_string(attempt);
}

// Owns the temporary file until it is renamed: closes and removes it on every error path.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& path) : target_(path) {
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      name_ = temporary_name(path, attempt);
      // 0666 & ~umask, like any new file; O_EXCL: never reuse an existing file.
      fd_ = ::open(name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) {
      const int error = errno;
      const std::filesystem::path dir = std::filesystem::path(path).parent_path();
      throw FileError(path, 0,
                      "cannot create a temporary file in '" + (dir.empty() ? "." : dir.string()) +
                          "': " + error_text(error));
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(name_.c_str());
  }

  void write_all(const std::string& content) {
    std::size_t done = 0;
    while (done < content.size()) {
      const ssize_t n = ::write(fd_, content.data() + done, content.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        fail("cannot write");
      }
      done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd_) != 0) fail("cannot flush to disk");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot close");
  }

  void commit() {
    if (::rename(name_.c_str(), target_.c_str()) != 0) fail("cannot rename the temporary file");
    committed_ = true;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(target_, 0, what + ": " + error_text(errno));
  }

  std::string target_;
  std::string name_;
  int fd_ = -1;
  bool committed_ = false;
};

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  if (path.empty()) throw FileError("(empty path)", 0, "no output file name");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw FileError(path, 0, "is a directory");
  TemporaryFile file(path);
  file.write_all(content);
  file.commit();
}

}  // namespace vrreg::io
