// SPDX-License-Identifier: Apache-2.0
#pragma once
// The served models the service's end-to-end fuzz harnesses (fuzz_serve_line_handler.cpp,
// fuzz_serve_http_handler.cpp) answer with: built once per process, written to a temporary
// directory, loaded by the service's own code (no sockets: the harnesses call the handlers the
// sessions call), and removed at exit.
//   "pose": kriging with the marker's orientations, 4 x 4 x 4 fiducials at 30 mm, the sensor frame
//           the robot's shifted by (1, 2, 3) mm, so that seeds can name points inside it:
//           sensor x 401..491, y -98..-8, z 103..193 mm
//   "grid": the paper's RRBC grid on the same fiducials' positions only
// Two services: "open" (no token) and "guarded" (token kToken); both keep an audit log.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "serve/service_impl.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/core/rotation.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::fuzz {

class ServedFixture {
 public:
  static constexpr const char* kToken = "fuzz-token-0123456789";

  ServedFixture() {
    std::string pattern = (std::filesystem::temp_directory_path() / "vrreg-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();
    dir_ = pattern;
    MeasurementSet cell = cell_with_orientations();
    RegisterOptions kriging;
    kriging.interpolation.method = InterpolationMethod::kKriging;
    io::write_model_json((dir_ / "pose.json").string(), register_fiducials(cell, kriging).model);
    for (Location& l : cell.locations) {
      l.q_robot_marker.reset();
      l.q_sensor_marker.reset();
    }
    io::write_model_json((dir_ / "grid.json").string(), register_fiducials(cell).model);
    open_ = std::make_unique<serve::Service::Impl>(options("open", ""), nullptr);
    guarded_ = std::make_unique<serve::Service::Impl>(options("guarded", kToken), nullptr);
  }
  ~ServedFixture() {
    open_.reset();
    guarded_.reset();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  ServedFixture(const ServedFixture&) = delete;
  ServedFixture& operator=(const ServedFixture&) = delete;

  serve::Service::Impl& open() { return *open_; }
  serve::Service::Impl& guarded() { return *guarded_; }

 private:
  static MeasurementSet cell_with_orientations() {
    Random rng(5);
    MeasurementSet set;
    set.source = "fuzz-cell.csv";
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          Location l;
          l.point = "f" + std::to_string(16 * i + 4 * j + k);
          l.role = Role::kFiducial;
          l.robot_m = Eigen::Vector3d(0.4, -0.1, 0.1) + 0.03 * Eigen::Vector3d(i, j, k);
          const Eigen::Vector3d error_m(1e-4 * std::sin(20 * l.robot_m.x()),
                                        1e-4 * std::cos(15 * l.robot_m.y()), 5e-5);
          l.sensor_m = l.robot_m + error_m + Eigen::Vector3d(1e-3, 2e-3, 3e-3) + rng.normal3(1e-5);
          l.n_readings = 1;
          const Eigen::Matrix3d commanded = rng.rotation();
          const Eigen::Vector3d error_rad(3e-3 * std::sin(8 * l.robot_m.x()),
                                          2e-3 * std::cos(6 * l.robot_m.y()), 1e-3);
          l.q_robot_marker = Eigen::Quaterniond(commanded);
          l.q_sensor_marker = Eigen::Quaterniond(rotation_exp(error_rad) * commanded);
          l.source_line = set.locations.size() + 2;
          set.locations.push_back(l);
        }
    return set;
  }

  serve::ServeOptions options(const std::string& name, const std::string& token) const {
    serve::ServeOptions o;
    o.models = {{"pose", (dir_ / "pose.json").string()}, {"grid", (dir_ / "grid.json").string()}};
    o.line = serve::Endpoint{"127.0.0.1", 0};
    o.http = serve::Endpoint{"127.0.0.1", 0};
    o.token = token;
    o.max_batch = 64;
    o.max_body_bytes = 64u << 10;
    o.reload_poll_ms = 0;
    o.audit.path = (dir_ / (name + "-audit.jsonl")).string();
    o.audit.max_bytes = 64u << 10;
    o.audit.keep = 1;
    return o;
  }

  std::filesystem::path dir_;
  std::unique_ptr<serve::Service::Impl> open_;
  std::unique_ptr<serve::Service::Impl> guarded_;
};

/// The process's fixture (built on first use).
inline ServedFixture& served() {
  static ServedFixture fixture;
  return fixture;
}

}  // namespace vrreg::fuzz

#ifdef VRREG_LIBFUZZER
// Fitting the served models takes over 10 s under the sanitizers: done in libFuzzer's set-up,
// whose time is not the first input's (it would otherwise time out on the empty input).
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  (void)vrreg::fuzz::served();
  return 0;
}
#endif

namespace vrreg::fuzz {

/// The numbers of a reply line "(a,b,...)\n"; throws Finding when it is not one.
inline std::vector<double> reply_numbers(const std::string& reply, const std::string& what) {
  require(reply.size() >= 3 && reply.front() == '(' && reply.substr(reply.size() - 2) == ")\n" &&
              reply.find('\n') == reply.size() - 1,
          what + ": a reply that is not one parenthesised line: " + reply);
  std::vector<double> numbers;
  std::size_t start = 1;
  while (start < reply.size() - 1) {
    std::size_t end = reply.find_first_of(",)", start);
    const std::string field = reply.substr(start, end - start);
    char* stop = nullptr;
    const double v = std::strtod(field.c_str(), &stop);
    require(!field.empty() && stop == field.c_str() + field.size() && std::isfinite(v) &&
                field.find_first_of("eE") == std::string::npos,
            what + ": a reply number a controller cannot read: " + reply);
    numbers.push_back(v);
    start = end + 1;
  }
  return numbers;
}

}  // namespace vrreg::fuzz
