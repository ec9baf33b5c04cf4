// SPDX-License-Identifier: Apache-2.0
#include "charts.hpp"

#include <algorithm>
#include <cmath>

namespace vrreg::report::charts {

double round_to(double value, int decimals) {
  if (!std::isfinite(value)) return value;
  const double f = std::pow(10.0, decimals);
  const double r = std::round(value * f) / f;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

nlohmann::json scaled(const Eigen::Ref<const Eigen::VectorXd>& values, double scale, int decimals) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < values.size(); ++i)
    out.push_back(round_to(values[i] * scale, decimals));
  return out;
}

nlohmann::json scaled(const std::vector<double>& values, double scale, int decimals) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values) out.push_back(round_to(v * scale, decimals));
  return out;
}

nlohmann::json xy_layout(const std::string& x_title, const std::string& y_title) {
  return {
      {"xaxis", {{"title", {{"text", x_title}}}, {"zeroline", false}, {"automargin", true}}},
      {"yaxis", {{"title", {{"text", y_title}}}, {"rangemode", "tozero"}, {"automargin", true}}},
      {"bargap", 0.05}};
}

nlohmann::json scene_layout(const std::string& x_title, const std::string& y_title,
                            const std::string& z_title) {
  return {{"scene",
           {{"xaxis", {{"title", {{"text", x_title}}}}},
            {"yaxis", {{"title", {{"text", y_title}}}}},
            {"zaxis", {{"title", {{"text", z_title}}}}},
            {"aspectmode", "data"},
            {"camera",
             {{"eye", {{"x", 1.45}, {"y", -1.45}, {"z", 0.7}}},
              {"center", {{"x", 0}, {"y", 0}, {"z", -0.12}}}}}}},
          {"legend",
           {{"orientation", "h"},
            {"x", 0},
            {"y", 1},
            {"yanchor", "top"},
            {"bgcolor", "rgba(255,255,255,0.7)"}}},
          {"margin", {{"l", 0}, {"r", 0}, {"t", 10}, {"b", 0}}}};
}

namespace {

nlohmann::json centres(const Histogram& h, double scale) {
  nlohmann::json x = nlohmann::json::array();
  for (std::size_t k = 0; k < h.counts.size(); ++k) {
    x.push_back(round_to((h.lo_m + (static_cast<double>(k) + 0.5) * h.bin_width_m) * scale, 6));
  }
  return x;
}

}  // namespace

nlohmann::json histogram_trace(const Histogram& h, double scale, const std::string& name,
                               const std::string& color) {
  return {{"type", "bar"},
          {"name", name},
          {"x", centres(h, scale)},
          {"y", h.counts},
          {"width", round_to(h.bin_width_m * scale, 6)},
          {"marker", {{"color", color}}},
          {"hovertemplate", "%{x} mm: %{y}<extra>" + name + "</extra>"}};
}

void whole_count_ticks(nlohmann::json& layout, const Histogram& h) {
  std::int64_t top = 0;
  for (std::int64_t c : h.counts) top = std::max(top, c);
  if (top <= 10) layout["yaxis"]["dtick"] = top <= 5 ? 1 : 2;
}

nlohmann::json histogram_step_trace(const Histogram& h, double scale, const std::string& name) {
  return {{"type", "scatter"}, {"mode", "lines"},
          {"name", name},      {"x", centres(h, scale)},
          {"y", h.counts},     {"line", {{"shape", "hvh"}, {"width", 1.8}}}};
}

nlohmann::json per_target_trace(const std::vector<double>& values_mm,
                                const std::vector<std::string>& labels, const std::string& name,
                                const std::string& color) {
  nlohmann::json x = nlohmann::json::array();
  for (std::size_t n = 0; n < values_mm.size(); ++n) x.push_back(n + 1);
  return {{"type", "bar"},
          {"name", name},
          {"x", x},
          {"y", scaled(values_mm, 1.0, 4)},
          {"text", labels},
          {"textposition", "none"},  // labels in the hover only
          {"marker", {{"color", color}}},
          {"hovertemplate", "n = %{x} (%{text}): %{y} mm<extra>" + name + "</extra>"}};
}

nlohmann::json scatter3d_trace(const Points3& points_m, const std::vector<std::string>& labels,
                               const std::string& name, const nlohmann::json& marker) {
  nlohmann::json xyz[3] = {nlohmann::json::array(), nlohmann::json::array(),
                           nlohmann::json::array()};
  for (Eigen::Index k = 0; k < points_m.cols(); ++k) {
    for (int a = 0; a < 3; ++a) xyz[a].push_back(round_to(points_m(a, k) * 1e3, 3));
  }
  nlohmann::json t = {{"type", "scatter3d"}, {"mode", "markers"}, {"name", name},    {"x", xyz[0]},
                      {"y", xyz[1]},         {"z", xyz[2]},       {"marker", marker}};
  if (!labels.empty()) {
    t["text"] = labels;
    t["hovertemplate"] = "%{text}<br>x %{x} mm, y %{y} mm, z %{z} mm<extra>" + name + "</extra>";
  }
  return t;
}

Histogram auto_histogram(const Eigen::Ref<const Eigen::VectorXd>& values, int target_bins) {
  double lo = values.size() ? values.minCoeff() : 0.0;
  double hi = values.size() ? values.maxCoeff() : 1.0;
  if (!(hi > lo)) {
    lo -= 0.5e-3;
    hi += 0.5e-3;
  }
  // A "nice" width: 1, 2 or 5 times a power of ten, near (hi - lo) / target_bins.
  const double raw = (hi - lo) / std::max(1, target_bins);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  const double width = raw <= p ? p : raw <= 2 * p ? 2 * p : raw <= 5 * p ? 5 * p : 10 * p;
  const double start = std::floor(lo / width) * width;
  const int bins = std::max(1, static_cast<int>(std::floor((hi - start) / width)) + 1);
  return histogram(values, bins, start, start + bins * width);
}

}  // namespace vrreg::report::charts
