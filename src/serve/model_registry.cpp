// SPDX-License-Identifier: Apache-2.0
#include "model_registry.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <utility>

#include "vrreg/core/check.hpp"
#include "vrreg/core/file_error.hpp"

namespace vrreg::serve {
namespace {

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > 64) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

ModelSource parse_model_source(const std::string& text) {
  ModelSource source;
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    source.path = text;
    source.name = std::filesystem::path(text).stem().string();
  } else {
    source.name = text.substr(0, eq);
    source.path = text.substr(eq + 1);
  }
  VRREG_THROW_UNLESS(!source.path.empty(), "model '" << text << "': no file given");
  VRREG_THROW_UNLESS(valid_name(source.name),
                     "model name '" << source.name
                                    << "': use letters, digits, '_', '-', '.' (at most 64), as "
                                       "NAME=FILE");
  return source;
}

ModelRegistry::FileStamp ModelRegistry::stamp_of(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return {};
  return {static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec,
          static_cast<long long>(st.st_size), static_cast<unsigned long long>(st.st_ino)};
}

ModelRegistry::ModelRegistry(const std::vector<ModelSource>& sources, Log log)
    : log_(std::move(log)) {
  VRREG_THROW_UNLESS(!sources.empty(), "no model to serve (--model FILE or NAME=FILE)");
  for (const ModelSource& source : sources) {
    for (const Slot& s : slots_) {
      VRREG_THROW_UNLESS(s.source.name != source.name,
                         "two models are named '" << source.name << "' (use NAME=FILE)");
    }
    Slot slot;
    slot.source = source;
    slot.stamp = stamp_of(source.path);
    slot.model = load_served_model(source.name, source.path);
    slots_.push_back(std::move(slot));
  }
}

std::shared_ptr<const ServedModel> ModelRegistry::find(const std::string& name) const {
  const std::lock_guard lock(mutex_);
  for (const Slot& s : slots_) {
    if (s.source.name == name) return s.model;
  }
  return nullptr;
}

std::vector<std::shared_ptr<const ServedModel>> ModelRegistry::all() const {
  const std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<const ServedModel>> out;
  for (const Slot& s : slots_) out.push_back(s.model);
  return out;
}

std::vector<std::string> ModelRegistry::last_errors() const {
  const std::lock_guard lock(mutex_);
  std::vector<std::string> out;
  for (const Slot& s : slots_) out.push_back(s.last_error);
  return out;
}

int ModelRegistry::reload(bool force) {
  const std::lock_guard one_at_a_time(reload_mutex_);
  int swapped = 0;
  for (std::size_t i = 0;; ++i) {
    ModelSource source;
    FileStamp before;
    std::string old_sha;
    {
      const std::lock_guard lock(mutex_);
      if (i >= slots_.size()) break;
      source = slots_[i].source;
      before = slots_[i].stamp;
      old_sha = slots_[i].model->identity().sha256;
    }
    const FileStamp now = stamp_of(source.path);
    if (!force && now == before) continue;
    // Loading runs without the lock: requests keep being answered by the old model meanwhile.
    std::shared_ptr<const ServedModel> loaded;
    std::string error;
    try {
      loaded = load_served_model(source.name, source.path);
    } catch (const std::exception& e) {
      error = e.what();
    }
    const std::lock_guard lock(mutex_);
    Slot& slot = slots_[i];
    slot.stamp = now;
    if (loaded) {
      const bool same = loaded->identity().sha256 == old_sha;
      slot.model = std::move(loaded);
      slot.last_error.clear();
      ++swapped;
      if (log_) {
        log_("model '" + source.name + "' reloaded from " + source.path + " (sha256 " +
             slot.model->identity().sha256.substr(0, 16) + (same ? ", unchanged content)" : ")"));
      }
    } else {
      slot.last_error = error;
      if (log_) {
        log_("model '" + source.name + "': reload failed, still serving sha256 " +
             old_sha.substr(0, 16) + ": " + error);
      }
    }
  }
  return swapped;
}

}  // namespace vrreg::serve
