// SPDX-License-Identifier: Apache-2.0
#pragma once
// Output files are written whole or not at all (design.md 6), and never replace anything but a
// regular file: docs/file-formats.md, "How outputs are written".
#include <functional>
#include <string>
#include <vector>

namespace vrreg::io {

/// Writes `content` to a temporary file `.vrreg-XXXXXX` beside `path`, flushes it to disk and
/// renames it over `path`; on any failure removes the temporary file and throws FileError naming
/// `path`. A symbolic link at `path` is written through (its target is replaced, the link stays);
/// a replaced file keeps its permission bits (and owner where allowed); a device, FIFO, socket,
/// directory or read-only file at `path` is refused, not replaced.
void write_file_atomically(const std::string& path, const std::string& content);

/// One output of a command: where it goes and what it holds.
struct OutputFile {
  std::string path{};
  std::string content{};
};

/// The outputs of one command, all or none: every file is written to its temporary file and
/// flushed first, then each is renamed over its path; a failure removes the temporary files, and
/// a rename that fails undoes the renames before it (a replaced file comes back). Throws what
/// write_file_atomically throws, for the output that failed.
void write_files_atomically(const std::vector<OutputFile>& files);

/// write_file_atomically with the content made piece by piece, so that a large output never sits in
/// memory whole: `next_piece(piece)` appends the next piece to the empty `piece` and returns false
/// after the last one. An exception from it removes the temporary file and propagates.
void write_file_atomically_in_pieces(const std::string& path,
                                     const std::function<bool(std::string&)>& next_piece);

/// Throws the FileError write_file_atomically(path, ...) would throw for what is at `path` now
/// (a device, FIFO, socket, directory or read-only file), so that a command refuses an output
/// before doing any work; nothing at `path` (or a writable regular file) passes.
void check_output_replaceable(const std::string& path);

/// For programs: on SIGINT and SIGTERM, removes the temporary files being written, then ends the
/// process by the signal as before. The library never installs signal handlers by itself; a
/// signal its caller ignores stays ignored.
void remove_temporary_files_on_signal();

}  // namespace vrreg::io
