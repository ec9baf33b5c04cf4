// SPDX-License-Identifier: Apache-2.0
// The service's bounds and what it says about refused requests: batches off the threads robots
// wait on, a connection budget per protocol, refused requests counted and logged (rate-limited),
// the extrapolation cap, the line bound with either line end, localhost, liveness without a token,
// and an audit log that must be a regular file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "serve_test_support.hpp"
#include "vrreg/core/file_error.hpp"
#include "vrreg/core/format.hpp"

// A namespace of its own: the unity build compiles this file with the other serve tests.
namespace vrreg::serve::testing::limits {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
using Clock = std::chrono::steady_clock;

std::string number(double v) { return format_general(v, 17); }

// The lattice cell's fiducials' bounding box, sensor frame [mm].
std::pair<Eigen::Vector3d, Eigen::Vector3d> sensor_box_mm() {
  const MeasuredPoints cell = lattice_cell();
  return {1000.0 * cell.sensor_m.rowwise().minCoeff(), 1000.0 * cell.sensor_m.rowwise().maxCoeff()};
}

// The reply `vrreg correct --extrapolate` gives for `sensor_mm`, as the line protocol prints it.
std::string expected_extrapolated(const RegistrationModel& model,
                                  const Eigen::Vector3d& sensor_mm) {
  MeasuredPoints p;
  p.sensor_m = sensor_mm / 1000.0;
  CorrectOptions options;
  options.extrapolate = true;
  const TargetCorrection c = correct(model, p, options).correction;
  EXPECT_EQ(c.stencils[0].status, StencilStatus::kExtrapolated);
  PointAnswer a;
  for (int k = 0; k < 3; ++k) a.robot_mm(k) = units::m_to_mm(c.corrected_robot_m(k, 0));
  a.sd_mm = units::m_to_mm(c.predicted_sd_m(0));
  return format_line_reply(a);
}

template <class Predicate>
bool eventually(Predicate done) {
  for (int i = 0; i < 500; ++i) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return done();
}

TEST(ServiceBatches, ALineRequestIsAnsweredWhileABatchRuns) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  ServeOptions o = local_options(path);
  o.threads = 1;  // one I/O thread: a batch answered on it would hold every line request
  o.batch_threads = 1;
  Service service(o, nullptr);
  service.start();
  const auto [lo, hi] = sensor_box_mm();
  nlohmann::json batch = {{"model", "cell"}, {"points", nlohmann::json::array()}};
  for (int i = 0; i < 10000; ++i) {
    const double t = (i % 97) / 97.0;
    const Eigen::Vector3d p = lo + t * (hi - lo);
    batch["points"].push_back({{"sensor_mm", {p.x(), p.y(), p.z()}}});
  }
  const std::string body = batch.dump();
  std::atomic<bool> batch_done{false};
  double batch_s = 0.0;
  std::string batch_reply;
  std::thread batcher([&] {
    const auto start = Clock::now();
    batch_reply = http_request(service.http_port(), "POST", "/v1/correct", body);
    batch_s = std::chrono::duration<double>(Clock::now() - start).count();
    batch_done = true;
  });
  LineClient c(service.line_port());
  double worst_s = 0.0;
  int asked_during_batch = 0;
  while (!batch_done) {
    const auto start = Clock::now();
    EXPECT_THAT(c.ask("cell 1 2 3\n"), StartsWith("(0,0,0,-3)"));
    worst_s = std::max(worst_s, std::chrono::duration<double>(Clock::now() - start).count());
    ++asked_during_batch;
  }
  batcher.join();
  ASSERT_THAT(batch_reply, StartsWith("200 "));
  EXPECT_EQ(nlohmann::json::parse(batch_reply.substr(4))["results"].size(), 10000u);
  // On the same thread the line request would wait for the whole batch.
  EXPECT_GT(asked_during_batch, 5) << "batch " << batch_s << " s";
  EXPECT_LT(worst_s, std::max(0.05, batch_s / 4)) << "batch " << batch_s << " s";
}

TEST(ServiceBatches, StoppingWhileABatchRunsIsClean) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  auto service = std::make_unique<Service>(local_options(path), nullptr);
  service->start();
  nlohmann::json batch = {{"model", "cell"}, {"points", nlohmann::json::array()}};
  for (int i = 0; i < 10000; ++i) batch["points"].push_back({{"sensor_mm", {1.0, 2.0, i * 1.0}}});
  const std::string body = batch.dump();
  std::thread batcher([&body, port = service->http_port()] {
    try {
      http_request(port, "POST", "/v1/correct", body);
    } catch (const std::exception&) {
      // The service stopping under the request: refused or reset, both are clean here.
    }
  });
  // Stop while the batch is in the service (slow builds: wait for its connection first).
  (void)eventually([&] { return service->stats().open_http_connections >= 1; });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  service.reset();  // stops and joins, the batch answered or dropped
  batcher.join();
}

TEST(ServiceConnections, IdleHttpConnectionsNeverTakeTheRobotsSlots) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  o.max_connections = 1;
  o.max_http_connections = 2;
  Service service(o, nullptr);
  service.start();
  boost::asio::io_context io;
  std::vector<boost::asio::ip::tcp::socket> idle;
  for (int i = 0; i < 2; ++i) {
    idle.emplace_back(io);
    idle.back().connect({boost::asio::ip::make_address("127.0.0.1"), service.http_port()});
  }
  ASSERT_TRUE(eventually([&] { return service.stats().open_http_connections == 2; }));
  // Over the HTTP budget: 503, or a reset when the refusal closes before the request is read.
  EXPECT_THAT(http_request(service.http_port(), "GET", "/v1/live", ""),
              AnyOf(StartsWith("503 "), StartsWith("closed")));
  LineClient robot(service.line_port());
  EXPECT_THAT(robot.ask("cell 1 2 3\n"), StartsWith("("));
  EXPECT_THAT(robot.ask("cell 1 2 3\n"), Not(StartsWith("(0,0,0,-6)")));
  LineClient second(service.line_port());  // over the line budget
  EXPECT_EQ(second.read_line(), "(0,0,0,-6)\n");
  const ServiceStats s = service.stats();
  EXPECT_EQ(s.rejected_connections, 2u);
  EXPECT_EQ(s.open_line_connections, 1);
  EXPECT_EQ(s.open_http_connections, 2);
}

TEST(ServiceLog, RefusedRequestsAreCountedLoggedAndAudited) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  o.audit.path = dir.file("audit.jsonl");
  std::vector<std::string> log;
  std::mutex log_mutex;
  Service service(o, [&](const std::string& m) {
    const std::lock_guard l(log_mutex);
    log.push_back(m);
  });
  service.start();
  {
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask("cell 1 2 banana\n"), "(0,0,0,-1)\n");
  }
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct", "{\"model\":"),
              StartsWith("400 "));
  const std::string health = http_request(service.http_port(), "GET", "/v1/health", "");
  ASSERT_THAT(health, StartsWith("200 "));
  const nlohmann::json counters = nlohmann::json::parse(health.substr(4))["counters"];
  EXPECT_EQ(counters["malformed_requests"], 2);
  EXPECT_EQ(counters["unauthorized_requests"], 0);
  EXPECT_EQ(counters["refusals"], 2);
  {
    const std::lock_guard l(log_mutex);
    ASSERT_GE(log.size(), 2u);
    EXPECT_THAT(log[0], HasSubstr("line request from 127.0.0.1:"));
    EXPECT_THAT(log[0], HasSubstr("banana"));
    EXPECT_THAT(log[1], HasSubstr("http request from 127.0.0.1:"));
  }
  // A flood is counted in full but logged a few lines at a time.
  {
    LineClient c(service.line_port());
    for (int i = 0; i < 100; ++i) c.ask("cell 1 2 banana\n");
  }
  EXPECT_EQ(service.stats().malformed, 102u);
  {
    const std::lock_guard l(log_mutex);
    EXPECT_LE(log.size(), 25u);
  }
  service.stop();
  const std::string audit = read_text(dir.file("audit.jsonl"));
  const nlohmann::json first = nlohmann::json::parse(audit.substr(0, audit.find('\n')));
  EXPECT_EQ(first["protocol"], "line");
  EXPECT_EQ(first["code"], 1);
  EXPECT_THAT(first["reason"].get<std::string>(), HasSubstr("banana"));
  EXPECT_THAT(first["client"].get<std::string>(), StartsWith("127.0.0.1:"));
}

TEST(ServiceLog, FailedAuthenticationsAreCountedAndLogged) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  o.token = "0123456789abcdef-secret";
  std::vector<std::string> log;
  std::mutex log_mutex;
  Service service(o, [&](const std::string& m) {
    const std::lock_guard l(log_mutex);
    log.push_back(m);
  });
  service.start();
  {
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask("auth not-the-token-at-all\n"), "(0,0,0,-5)\n");
  }
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct", "{}",
                           "Authorization: Bearer nope\r\n"),
              StartsWith("401 "));
  EXPECT_EQ(service.stats().unauthorized, 2u);
  const std::lock_guard l(log_mutex);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_THAT(log[0], HasSubstr("(5 unauthorized)"));
  EXPECT_THAT(log[0], Not(HasSubstr("not-the-token")));  // a near-miss token is no log line
}

TEST(ServiceExtrapolation, FarPointsAreRefusedWithTheirOwnCodeAndTheCapIsSettable) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  const RegistrationModel model = io::read_model_json(path);
  const auto [lo, hi] = sensor_box_mm();
  const double diagonal = (hi - lo).norm();
  const Eigen::Vector3d near = hi + Eigen::Vector3d(0.5 * diagonal, 0, 0);
  const Eigen::Vector3d far = hi + Eigen::Vector3d(1.5 * diagonal, 0, 0);
  const auto line = [](const Eigen::Vector3d& p) {
    return "cell " + number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + " extrapolate\n";
  };
  {
    Service service(local_options(path), nullptr);
    service.start();
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask(line(near)), expected_extrapolated(model, near));  // as vrreg correct
    EXPECT_EQ(c.ask(line(far)), "(0,0,0,-8)\n");
    EXPECT_EQ(c.ask("cell 1e9 1e9 1e9 extrapolate\n"), "(0,0,0,-8)\n");
    EXPECT_EQ(c.ask("cell 1e9 1e9 1e9 extrapolate quat 0 0 0 1\n"), "(0,0,0,0,0,0,0,-4,-4)\n");
    const std::string http = http_request(
        service.http_port(), "POST", "/v1/correct",
        nlohmann::json{
            {"model", "cell"}, {"sensor_mm", {far.x(), far.y(), far.z()}}, {"extrapolate", true}}
            .dump());
    ASSERT_THAT(http, StartsWith("422 "));
    const nlohmann::json j = nlohmann::json::parse(http.substr(4));
    EXPECT_EQ(j["code"], 8);
    EXPECT_EQ(j["status"], "too far to extrapolate");
    EXPECT_TRUE(j.contains("uncorrected_robot_mm"));
  }
  ServeOptions wide = local_options(path);
  wide.max_extrapolation = 2.0;
  Service service(wide, nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_EQ(c.ask(line(far)), expected_extrapolated(model, far));
  wide.max_extrapolation = 0.0;
  EXPECT_THROW(wide.validate(), InputError);
  wide.max_extrapolation = std::numeric_limits<double>::infinity();
  EXPECT_NO_THROW(wide.validate());
}

TEST(ServiceLines, TheBoundIsOnTheRequestWhicheverLineEnd) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  Service service(local_options(dir.file("cell.json")), nullptr);
  service.start();
  std::string request = "cell 1 2 3";
  request += std::string(1024 - request.size(), ' ');
  ASSERT_EQ(request.size(), 1024u);
  LineClient c(service.line_port());
  const std::string answer = c.ask(request + "\n");
  EXPECT_THAT(answer, StartsWith("("));
  EXPECT_NE(answer, "(0,0,0,-6)\n");
  EXPECT_EQ(c.ask(request + "\r\n"), answer);
  // One '\r' is the line end's; a second is a control character in the request.
  EXPECT_EQ(c.ask("cell 1 2 3\r\r\n"), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask(request + " \r\n"), "(0,0,0,-6)\n");  // 1 025 bytes
  EXPECT_EQ(c.read_line(), "");
  LineClient d(service.line_port());
  EXPECT_EQ(d.ask(request + " \n"), "(0,0,0,-6)\n");
  EXPECT_EQ(d.read_line(), "");
}

TEST(ServiceAddresses, LocalhostIsLoopback) {
  EXPECT_EQ(parse_endpoint("localhost:0").address, "localhost");
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  o.line = parse_endpoint("localhost:0");
  o.http = parse_endpoint("LOCALHOST:0");
  EXPECT_NO_THROW(o.validate());
  Service service(o, nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_THAT(c.ask("cell 1 2 3\n"), StartsWith("("));
}

TEST(ServiceHealth, LivenessNeedsNoTokenAndSaysNothingElse) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  o.token = "0123456789abcdef-secret";
  Service service(o, nullptr);
  service.start();
  EXPECT_EQ(http_request(service.http_port(), "GET", "/v1/live", ""), R"(200 {"status":"live"})");
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/live", ""), StartsWith("400 "));
  EXPECT_THAT(http_request(service.http_port(), "GET", "/v1/health", ""), StartsWith("401 "));
  const std::string health = http_request(service.http_port(), "GET", "/v1/health", "",
                                          "Authorization: Bearer 0123456789abcdef-secret\r\n");
  ASSERT_THAT(health, StartsWith("200 "));
  const nlohmann::json model = nlohmann::json::parse(health.substr(4))["models"][0];
  ASSERT_TRUE(model.contains("last_reload_error"));  // listed also when there was none
  EXPECT_TRUE(model["last_reload_error"].is_null());
}

TEST(ServiceAuditLog, AFifoOrADeviceIsRefusedAtStart) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options(dir.file("cell.json"));
  ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0600), 0);
  o.audit.path = dir.file("fifo");
  const auto start = Clock::now();
  try {
    Service service(o, nullptr);
    ADD_FAILURE() << "a FIFO was accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("not a regular file"));
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 5.0);  // no hang
  if (std::filesystem::exists("/dev/full")) {
    o.audit.path = "/dev/full";
    EXPECT_THROW(Service(o, nullptr), FileError);
  }
  o.audit.path = dir.file("audit.jsonl");
  EXPECT_NO_THROW(Service(o, nullptr));
}

}  // namespace
}  // namespace vrreg::serve::testing::limits
