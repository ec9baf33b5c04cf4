// SPDX-License-Identifier: Apache-2.0
#pragma once
// Cells, models and a blocking client for the service's tests.
#include <utility>  // before Boost.Asio 1.74, whose awaitable.hpp uses std::exchange

#include <boost/asio.hpp>
#include <cmath>
#include <random>
#include <string>

#include "io_test_helpers.hpp"
#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "vrreg/core/units.hpp"
#include "vrreg/io/model_json.hpp"
#include "vrreg/vrreg.hpp"

namespace vrreg::serve::testing {

using vrreg::testing::read_text;
using vrreg::testing::TempDir;

/// A 5 x 5 x 5 lattice at 20 mm with a smooth robot error and 0.01 mm noise, sensor = robot
/// turned and shifted: fiducials for a model of `method`.
inline MeasuredPoints lattice_cell(unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1e-5);
  MeasuredPoints cell;
  const int n = 5;
  cell.robot_m.resize(3, n * n * n);
  cell.sensor_m.resize(3, n * n * n);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const Eigen::Vector3d t(-1.0, 0.3, 0.2);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int l = 0; l < n; ++l, ++k) {
        const Eigen::Vector3d robot(0.4 + 0.02 * i, -0.1 + 0.02 * j, 0.3 + 0.02 * l);
        const Eigen::Vector3d error(1.5e-4 * std::sin(robot.x() / 0.06), 1.2e-4 * std::cos(robot.y() / 0.045),
                                    1e-4 * std::sin(robot.z() / 0.05));
        cell.robot_m.col(k) = robot;
        Eigen::Vector3d measured = robot + error;
        for (int a = 0; a < 3; ++a) measured(a) += noise(rng);
        cell.sensor_m.col(k) = R.transpose() * (measured - t);
      }
    }
  }
  return cell;
}

/// Registers the lattice cell with `method` and writes the model to `path`.
inline RegistrationModel write_model(const std::string& path, InterpolationMethod method,
                                     unsigned seed = 7) {
  RegisterOptions options;
  options.interpolation.method = method;
  const RegisterResult r = register_fiducials(lattice_cell(seed), options);
  io::write_model_json(path, r.model);
  return r.model;
}

/// The reply line the service must send for `sensor_mm`: `vrreg::correct`'s numbers (what the
/// command writes), formatted as the line protocol formats them.
inline std::string expected_reply(const RegistrationModel& model, const Eigen::Vector3d& sensor_mm) {
  MeasuredPoints p;
  p.sensor_m.resize(3, 1);
  for (int a = 0; a < 3; ++a) p.sensor_m(a, 0) = sensor_mm(a) / units::kMillimetresPerMetre;
  const TargetCorrection c = correct(model, p).correction;
  if (c.stencils[0].status != StencilStatus::kOk) {
    return format_line_reply(PointAnswer::refusal(ReplyCode::kNotCorrectable, ""));
  }
  PointAnswer a;
  for (int k = 0; k < 3; ++k) a.robot_mm(k) = units::m_to_mm(c.corrected_robot_m(k, 0));
  a.sd_mm = c.predicted_sd_m.size() > 0 ? units::m_to_mm(c.predicted_sd_m(0)) : 0.0;
  return format_line_reply(a);
}

/// A blocking line-protocol client.
class LineClient {
 public:
  explicit LineClient(unsigned short port) : socket_(io_) {
    socket_.connect({boost::asio::ip::make_address("127.0.0.1"), port});
    socket_.set_option(boost::asio::ip::tcp::no_delay(true));
  }
  /// Sends `bytes` as they are.
  void send(const std::string& bytes) { boost::asio::write(socket_, boost::asio::buffer(bytes)); }
  /// The next reply line, '\n' included; "" when the service closed the connection.
  std::string read_line() {
    boost::system::error_code ec;
    const std::size_t n = boost::asio::read_until(socket_, boost::asio::dynamic_buffer(buffer_), '\n', ec);
    if (ec) return "";
    std::string line = buffer_.substr(0, n);
    buffer_.erase(0, n);
    return line;
  }
  std::string ask(const std::string& line) {
    send(line);
    return read_line();
  }
  boost::asio::ip::tcp::socket& socket() { return socket_; }

 private:
  boost::asio::io_context io_;
  boost::asio::ip::tcp::socket socket_;
  std::string buffer_;
};

/// A service on loopback (ports chosen by the system), 2 threads, no reload polling.
inline ServeOptions local_options(const std::vector<ModelSource>& models) {
  ServeOptions o;
  o.models = models;
  o.line = Endpoint{"127.0.0.1", 0};
  o.http = Endpoint{"127.0.0.1", 0};
  o.threads = 2;
  o.reload_poll_ms = 0;
  return o;
}
/// The same serving the model file `path` as "cell".
inline ServeOptions local_options(const std::string& path) { return local_options({{"cell", path}}); }

/// One HTTP/1.1 request on a fresh connection; returns "STATUS BODY".
std::string http_request(unsigned short port, const std::string& method, const std::string& target,
                         const std::string& body, const std::string& extra_headers = "");

}  // namespace vrreg::serve::testing
