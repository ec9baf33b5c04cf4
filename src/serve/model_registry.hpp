// SPDX-License-Identifier: Apache-2.0
#pragma once
// The served models by name, each swapped atomically when its file changes (or on SIGHUP): a
// request takes the model that is current when it starts and finishes on it; a file that fails to
// load leaves the old model serving, and the failure is reported.
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "served_model.hpp"

namespace vrreg::serve {

/// A model to serve: its name and file.
struct ModelSource {
  std::string name;
  std::string path;
};

/// "NAME=FILE" or "FILE" (named by the file's stem); throws InputError on an invalid name.
ModelSource parse_model_source(const std::string& text);

class ModelRegistry {
 public:
  using Log = std::function<void(const std::string&)>;

  /// Loads every model (throws FileError on the first that fails: a service starts whole or not).
  ModelRegistry(const std::vector<ModelSource>& sources, Log log);

  /// The model named `name` as it is now, or null.
  [[nodiscard]] std::shared_ptr<const ServedModel> find(const std::string& name) const;
  /// Every model as it is now, in the order given.
  [[nodiscard]] std::vector<std::shared_ptr<const ServedModel>> all() const;

  /// Reloads the models whose file changed (modification time, size or inode) since they were
  /// read, or every model when `force`; returns how many were swapped in.
  int reload(bool force);

  /// Reloads that failed since the start (the health endpoint reports the last one per model).
  [[nodiscard]] std::vector<std::string> last_errors() const;

 private:
  struct FileStamp {
    long long mtime_ns = 0;
    long long size = 0;
    unsigned long long inode = 0;
    bool operator==(const FileStamp&) const = default;
  };
  struct Slot {
    ModelSource source;
    std::shared_ptr<const ServedModel> model;
    FileStamp stamp;            ///< of the file when it was last tried
    std::string last_error;     ///< of the last failed reload, empty when it loaded
  };
  static FileStamp stamp_of(const std::string& path);

  mutable std::mutex mutex_;    ///< guards slots_' pointers and stamps (never held while loading)
  std::vector<Slot> slots_;
  std::mutex reload_mutex_;     ///< one reload at a time
  Log log_;
};

}  // namespace vrreg::serve
