// SPDX-License-Identifier: Apache-2.0
#include "values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "vrreg/core/check.hpp"
#include "vrreg/core/format.hpp"

namespace vrreg::report::detail {
namespace {

const nlohmann::json* member(const nlohmann::json& obj, const std::string& key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return nullptr;
  return &*it;
}

std::optional<Stat> as_stat(const nlohmann::json& v, const std::string& what) {
  if (v.is_number()) return Stat{v.get<double>(), std::nullopt};
  if (v.is_object() && v.contains("mean") && v["mean"].is_null()) return std::nullopt;
  if (v.is_object() && v.contains("mean") && v["mean"].is_number()) {
    Stat s{v["mean"].get<double>(), std::nullopt};
    if (v.contains("sd") && v["sd"].is_number()) s.sd = v["sd"].get<double>();
    return s;
  }
  VRREG_THROW_UNLESS(false, what << ": expected a number or {\"mean\": .., \"sd\": ..}, got "
                                 << v.dump().substr(0, 60));
  return std::nullopt;
}

}  // namespace

std::optional<Stat> stat_at(const nlohmann::json& obj, const std::string& key,
                            const std::string& where) {
  const nlohmann::json* v = member(obj, key);
  if (!v) return std::nullopt;
  return as_stat(*v, where + "." + key);
}

std::optional<int> int_at(const nlohmann::json& obj, const std::string& key,
                          const std::string& where) {
  const nlohmann::json* v = member(obj, key);
  if (!v) return std::nullopt;
  VRREG_THROW_UNLESS(v->is_number_integer(),
                     where << "." << key << ": expected an integer, got " << v->dump());
  return v->get<int>();
}

std::optional<std::string> string_at(const nlohmann::json& obj, const std::string& key,
                                     const std::string& where) {
  const nlohmann::json* v = member(obj, key);
  if (!v) return std::nullopt;
  VRREG_THROW_UNLESS(v->is_string(), where << "." << key << ": expected a string");
  return v->get<std::string>();
}

std::vector<double> numbers_at(const nlohmann::json& obj, const std::string& key,
                               const std::string& where) {
  std::vector<double> out;
  const nlohmann::json* v = member(obj, key);
  if (!v) return out;
  VRREG_THROW_UNLESS(v->is_array(), where << "." << key << ": expected an array of numbers");
  for (std::size_t i = 0; i < v->size(); ++i) {
    const auto s = (*v)[i].is_null()
                       ? std::nullopt
                       : as_stat((*v)[i], where + "." + key + "[" + std::to_string(i) + "]");
    out.push_back(s ? s->mean : std::nan(""));
  }
  return out;
}

std::vector<std::string> strings_at(const nlohmann::json& obj, const std::string& key,
                                    const std::string& where) {
  std::vector<std::string> out;
  const nlohmann::json* v = member(obj, key);
  if (!v) return out;
  VRREG_THROW_UNLESS(v->is_array(), where << "." << key << ": expected an array of labels");
  for (const nlohmann::json& e : *v) out.push_back(e.is_string() ? e.get<std::string>() : e.dump());
  return out;
}

std::string fixed(double value, int decimals) { return format_fixed(value, decimals); }

std::string stat_text(const std::optional<Stat>& value, int decimals) {
  if (!value) return "—";
  std::string out = fixed(value->mean, decimals);
  if (value->sd) out += " ± " + fixed(*value->sd, decimals);
  return out;
}

namespace {

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = 0.5 * static_cast<double>(i + j) + 1.0;
    i = j + 1;
  }
  return r;
}

}  // namespace

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n < 2) return 0.0;
  const std::vector<double> ra = ranks({a.begin(), a.begin() + static_cast<long>(n)});
  const std::vector<double> rb = ranks({b.begin(), b.begin() + static_cast<long>(n)});
  const double ma = std::accumulate(ra.begin(), ra.end(), 0.0) / static_cast<double>(n);
  const double mb = std::accumulate(rb.begin(), rb.end(), 0.0) / static_cast<double>(n);
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (ra[i] - ma) * (rb[i] - mb);
    saa += (ra[i] - ma) * (ra[i] - ma);
    sbb += (rb[i] - mb) * (rb[i] - mb);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace vrreg::report::detail
