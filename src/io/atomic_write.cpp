// SPDX-License-Identifier: Apache-2.0
#include "vrreg/io/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "file_kind.hpp"
#include "temporary_files.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::io {
namespace {

namespace fs = std::filesystem;

std::string error_text(int error) { return std::strerror(error); }

// The file a symbolic link at `path` finally names (`path` itself when it is no link): outputs
// are written through links, so that the link stays and what it points to is replaced.
fs::path follow_symlinks(const std::string& path) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const fs::path next = fs::read_symlink(p, ec);
    if (ec) throw FileError(path, 0, "cannot read the symbolic link: " + ec.message());
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  throw FileError(path, 0, "too many levels of symbolic links");
}

bool read_only(const fs::path& target, const struct stat& st) {
  // Root may write anything: honour the file's own mode bits instead.
  if (::geteuid() == 0) return (st.st_mode & S_IWUSR) == 0;
  return ::access(target.c_str(), W_OK) != 0;
}

// What is at `target` now: nothing, or a regular file that may be replaced (its stat).
std::optional<struct stat> replaceable_target(const std::string& path, const fs::path& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno == ENOENT) return std::nullopt;
    throw FileError(path, 0, "cannot inspect: " + error_text(errno));
  }
  if (!S_ISREG(st.st_mode)) {
    throw FileError(path, 0,
                    std::string(detail::file_kind(st.st_mode)) +
                        ", not a regular file: outputs replace only regular files");
  }
  if (read_only(target, st)) {
    throw FileError(path, 0,
                    "is read-only: not replaced (make it writable or choose another name)");
  }
  return st;
}

// ".vrreg-" and six letters or digits: short, so that a 255-byte target name still works.
std::string temporary_basename() {
  static std::atomic<unsigned long long> counter{0};
  static constexpr char kChars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  unsigned long long x =
      static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
      (static_cast<unsigned long long>(::getpid()) << 40) ^ (counter++ * 0x9E3779B97F4A7C15ULL);
  // splitmix64 finaliser: neighbouring counters give unrelated names.
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  x ^= x >> 31;
  std::string name = ".vrreg-";
  for (int i = 0; i < 6; ++i, x /= 62) name += kChars[x % 62];
  return name;
}

// An output renamed into place that can be taken back until the command's other outputs are in
// place too: the file it replaced lives on as a hard link beside it, removed when this goes.
class Replacement {
 public:
  Replacement(fs::path target, bool existed) : target_(std::move(target)), existed_(existed) {
    if (!existed_) return;
    const fs::path dir = target_.parent_path().empty() ? fs::path(".") : target_.parent_path();
    for (int attempt = 0; attempt < 100; ++attempt) {
      std::string name = (dir / temporary_basename()).string();
      const int slot = detail::remember_temporary(name);
      if (::link(target_.c_str(), name.c_str()) == 0) {
        backup_ = std::move(name);
        slot_ = slot;
        return;
      }
      const int error = errno;
      detail::forget_temporary(slot);
      if (error != EEXIST) return;  // no hard links here: this one output cannot be put back
    }
  }
  Replacement(Replacement&& other) noexcept
      : target_(std::move(other.target_)),
        backup_(std::exchange(other.backup_, {})),
        existed_(other.existed_),
        slot_(std::exchange(other.slot_, -1)) {}
  Replacement(const Replacement&) = delete;
  Replacement& operator=(const Replacement&) = delete;
  Replacement& operator=(Replacement&&) = delete;
  ~Replacement() {
    if (!backup_.empty()) ::unlink(backup_.c_str());
    detail::forget_temporary(slot_);
  }

  // What was at the target before comes back: the replaced file, or nothing.
  void undo() {
    if (!backup_.empty()) {
      if (::rename(backup_.c_str(), target_.c_str()) == 0) backup_.clear();
    } else if (!existed_) {
      ::unlink(target_.c_str());
    }
  }

 private:
  fs::path target_;
  std::string backup_;
  bool existed_;
  int slot_ = -1;
};

// Owns the temporary file until it is renamed: closes and removes it on every error path, and
// lists it for the signal handler (remove_temporary_files_on_signal) meanwhile.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& path, const fs::path& target,
                const std::optional<struct stat>& existing)
      : path_(path), target_(target) {
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    int error = 0;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      name_ = (dir / temporary_basename()).string();
      // Listed before it exists, so that no moment leaves it unlisted; a random name taken by
      // another file (EEXIST) is forgotten before the next try.
      slot_ = detail::remember_temporary(name_);
      // 0666 & ~umask, like any new file; O_EXCL: never reuse an existing file.
      fd_ = ::open(name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      error = errno;
      if (fd_ >= 0) break;
      detail::forget_temporary(slot_);
      slot_ = -1;
      if (error != EEXIST) break;
    }
    if (fd_ < 0) {
      throw FileError(
          path, 0,
          "cannot create a temporary file in '" + dir.string() + "': " + error_text(error));
    }
    if (existing) keep_owner_and_mode(*existing);
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(name_.c_str());
    detail::forget_temporary(slot_);
  }

  void write_all(const std::string& content) {
    write_piece(content);
    finish();
  }

  void write_piece(const std::string& content) {
    std::size_t done = 0;
    while (done < content.size()) {
      const ssize_t n = ::write(fd_, content.data() + done, content.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        fail("cannot write");
      }
      done += static_cast<std::size_t>(n);
    }
  }

  void finish() {
    if (::fsync(fd_) != 0) fail("cannot flush to disk");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot close");
  }

  // commit(), keeping what it replaces so that it can be undone.
  Replacement commit_undoably(bool existed) {
    Replacement replacement(target_, existed);
    commit();
    return replacement;
  }

  void commit() {
    // A signal between the rename and forget_temporary() unlinks a name that is gone: harmless.
    if (::rename(name_.c_str(), target_.c_str()) != 0) fail("cannot rename the temporary file");
    committed_ = true;
    detail::forget_temporary(slot_);
    slot_ = -1;
  }

 private:
  // The replaced file's owner (where we may set it: root, or our own group) before its mode,
  // since chown clears set-id bits.
  void keep_owner_and_mode(const struct stat& existing) {
    if (::fchown(fd_, existing.st_uid, existing.st_gid) != 0) {
      // Not permitted for a non-root user on another's group: the new file stays ours.
    }
    if (::fchmod(fd_, existing.st_mode & 07777) != 0) fail("cannot keep the file's permissions");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(path_, 0, what + ": " + error_text(errno));
  }

  std::string path_;
  fs::path target_;
  std::string name_;
  int fd_ = -1;
  int slot_ = -1;
  bool committed_ = false;
};

}  // namespace

void check_output_replaceable(const std::string& path) {
  (void)replaceable_target(path, follow_symlinks(path));
}

void write_file_atomically(const std::string& path, const std::string& content) {
  if (path.empty()) throw FileError("(empty path)", 0, "no output file name");
  const fs::path target = follow_symlinks(path);
  const std::optional<struct stat> existing = replaceable_target(path, target);
  TemporaryFile file(path, target, existing);
  file.write_all(content);
  file.commit();
}

void write_files_atomically(const std::vector<OutputFile>& files) {
  struct Pending {
    std::unique_ptr<TemporaryFile> file;
    bool existed;
  };
  std::vector<Pending> pending;
  pending.reserve(files.size());
  for (const OutputFile& f : files) {
    if (f.path.empty()) throw FileError("(empty path)", 0, "no output file name");
    const fs::path target = follow_symlinks(f.path);
    const std::optional<struct stat> existing = replaceable_target(f.path, target);
    pending.push_back(
        {std::make_unique<TemporaryFile>(f.path, target, existing), existing.has_value()});
    pending.back().file->write_all(f.content);
  }
  // Every output is on disk under its temporary name: only the renames remain.
  std::vector<Replacement> done;
  done.reserve(pending.size());
  try {
    for (Pending& p : pending) done.push_back(p.file->commit_undoably(p.existed));
  } catch (...) {
    for (auto it = done.rbegin(); it != done.rend(); ++it) it->undo();
    throw;
  }
}

void write_file_atomically_in_pieces(const std::string& path,
                                     const std::function<bool(std::string&)>& next_piece) {
  if (path.empty()) throw FileError("(empty path)", 0, "no output file name");
  const fs::path target = follow_symlinks(path);
  const std::optional<struct stat> existing = replaceable_target(path, target);
  TemporaryFile file(path, target, existing);
  std::string piece;
  bool more = true;
  while (more) {
    piece.clear();
    more = next_piece(piece);
    file.write_piece(piece);
  }
  file.finish();
  file.commit();
}

}  // namespace vrreg::io
