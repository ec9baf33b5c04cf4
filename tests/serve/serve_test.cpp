// SPDX-License-Identifier: Apache-2.0
// The service end to end, in process on ports the system picks: the same numbers as
// `vrreg correct`, refusals that say why, bounds, tokens, hot reload and the audit log.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "serve/snippets.hpp"
#include "serve_test_support.hpp"
#include "urscript_text.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::serve::testing {

std::string http_request(unsigned short port, const std::string& method, const std::string& target,
                         const std::string& body, const std::string& extra_headers) {
  boost::asio::io_context io;
  boost::asio::ip::tcp::socket socket(io);
  socket.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  const std::string request = method + " " + target + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n" +
                              extra_headers + "Content-Length: " + std::to_string(body.size()) +
                              "\r\n\r\n" + body;
  boost::system::error_code ec;
  // A refused body is answered before it is all sent: read the answer even if the write broke.
  boost::asio::write(socket, boost::asio::buffer(request), ec);
  boost::beast::flat_buffer buffer;
  boost::beast::http::response<boost::beast::http::string_body> response;
  boost::beast::http::read(socket, buffer, response, ec);
  if (ec) return "closed " + ec.message();
  return std::to_string(response.result_int()) + " " + response.body();
}

namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

bool is_refusal(const std::string& reply) { return reply.rfind("(0,0,0,-", 0) == 0; }

std::string request_line(const std::string& model, const Eigen::Vector3d& sensor_mm) {
  return model + " " + format_general(sensor_mm.x(), 17) + " " + format_general(sensor_mm.y(), 17) +
         " " + format_general(sensor_mm.z(), 17) + "\n";
}

// Sensor points inside the lattice cell (between its fiducials) and a few far outside.
std::vector<Eigen::Vector3d> sensor_points_mm(int n, unsigned seed) {
  const MeasuredPoints cell = lattice_cell();
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<Eigen::Index> pick(0, cell.size() - 1);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) {
    const double s = t(rng);
    const Eigen::Vector3d p = s * cell.sensor_m.col(pick(rng)) + (1 - s) * cell.sensor_m.col(pick(rng));
    out.push_back(p * 1000.0);
  }
  out.emplace_back(10000.0, 0.0, 0.0);
  return out;
}

TEST(Service, RepliesEqualCorrectForEveryMethodOfTheCell) {
  TempDir dir;
  for (const InterpolationMethod method :
       {InterpolationMethod::kKriging, InterpolationMethod::kRbf, InterpolationMethod::kLinear,
        InterpolationMethod::kTrilinear}) {
    const std::string path = dir.file(std::string(to_string(method)) + ".json");
    write_model(path, method);
    const RegistrationModel model = io::read_model_json(path);
    Service service(local_options({{"cell", path}}), nullptr);
    service.start();
    LineClient client(service.line_port());
    int ok = 0;
    for (const Eigen::Vector3d& p : sensor_points_mm(60, 3)) {
      const std::string expected = expected_reply(model, p);
      EXPECT_EQ(client.ask(request_line("cell", p)), expected) << to_string(method);
      ok += is_refusal(expected) ? 0 : 1;
    }
    EXPECT_GE(ok, 45) << to_string(method);  // the check is on corrected points, not refusals
  }
}

TEST(Service, RefusalsCarryTheirCodeAndTheConnectionGoesOn) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kKriging);
  Service service(local_options({parse_model_source(dir.file("cell.json"))}), nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_EQ(c.ask("nope 1 2 3\n"), "(0,0,0,-2)\n");
  EXPECT_EQ(c.ask("cell 1 2\n"), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask("cell nan 0 0\n"), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask("cell 1e400 0 0\n"), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask("\n"), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask("cell 10000 0 0\n"), "(0,0,0,-3)\n");  // outside the support: never silent
  // Metres away from an 80 mm cell: beyond the extrapolation cap, refused with its own code.
  EXPECT_EQ(c.ask("cell 10000 0 0 extrapolate\r\n"), "(0,0,0,-8)\n");
  EXPECT_EQ(c.ask(std::string("cell 1 2 3\x01\n")), "(0,0,0,-1)\n");
  EXPECT_EQ(c.ask("cell +-767.2 0 0\n"), "(0,0,0,-1)\n");  // two signs: a typing error
  const ServiceStats s = service.stats();
  EXPECT_EQ(s.refusals, 9u);
  EXPECT_EQ(s.malformed, 6u);
}

TEST(Service, ALineLongerThanTheBoundIsRefusedAndClosed) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  Service service(local_options({parse_model_source(dir.file("cell.json"))}), nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_EQ(c.ask(std::string(5000, 'x') + "\n"), "(0,0,0,-6)\n");
  EXPECT_EQ(c.read_line(), "");  // closed
}

TEST(Service, ConnectionsBeyondTheBoundAreRefusedNotQueued) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options({parse_model_source(dir.file("cell.json"))});
  o.max_connections = 2;
  Service service(o, nullptr);
  service.start();
  LineClient a(service.line_port());
  LineClient b(service.line_port());
  EXPECT_THAT(a.ask("cell 1 2 3\n"), StartsWith("("));
  EXPECT_THAT(b.ask("cell 1 2 3\n"), StartsWith("("));
  LineClient c(service.line_port());
  EXPECT_EQ(c.read_line(), "(0,0,0,-6)\n");
  EXPECT_EQ(service.stats().rejected_connections, 1u);
}

TEST(Service, IdleConnectionsAreClosed) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options({parse_model_source(dir.file("cell.json"))});
  o.idle_timeout_s = 0.2;
  Service service(o, nullptr);
  service.start();
  LineClient c(service.line_port());
  EXPECT_EQ(c.read_line(), "");  // returns when the service closes, after 0.2 s
}

TEST(Service, TokenIsRequiredBeforeAnyCorrection) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options({parse_model_source(dir.file("cell.json"))});
  o.token = "0123456789abcdef-secret";
  Service service(o, nullptr);
  service.start();
  {
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask("cell 1 2 3\n"), "(0,0,0,-5)\n");
    EXPECT_EQ(c.read_line(), "");
  }
  {
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask("auth wrong-token-000000\n"), "(0,0,0,-5)\n");
    EXPECT_EQ(c.read_line(), "");
  }
  {
    LineClient c(service.line_port());
    EXPECT_EQ(c.ask("auth 0123456789abcdef-secret\n"), "(1)\n");
    EXPECT_THAT(c.ask("cell 1 2 3\n"), StartsWith("("));
  }
  EXPECT_THAT(http_request(service.http_port(), "GET", "/v1/health", ""), StartsWith("401 "));
  EXPECT_EQ(service.stats().unauthorized, 3u);
  EXPECT_THAT(http_request(service.http_port(), "GET", "/v1/health", "",
                           "Authorization: Bearer 0123456789abcdef-secret\r\n"),
              StartsWith("200 "));
}

TEST(Service, RemoteAddressesNeedToBeAllowedAndATokenGiven) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kLinear);
  ServeOptions o = local_options({parse_model_source(dir.file("cell.json"))});
  o.line = Endpoint{"0.0.0.0", 0};
  EXPECT_THROW(o.validate(), InputError);
  o.allow_remote = true;
  EXPECT_THROW(o.validate(), InputError);
  o.token = "short";
  EXPECT_THROW(o.validate(), InputError);
  o.token = "a-long-enough-token";
  EXPECT_NO_THROW(o.validate());
}

TEST(Service, HttpAnswersAsTheLineProtocolAndBatches) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  const RegistrationModel model = io::read_model_json(path);
  Service service(local_options({{"cell", path}}), nullptr);
  service.start();
  const std::vector<Eigen::Vector3d> points = sensor_points_mm(10, 5);
  nlohmann::json batch = {{"model", "cell"}, {"points", nlohmann::json::array()}};
  for (const Eigen::Vector3d& p : points) {
    batch["points"].push_back({{"sensor_mm", {p.x(), p.y(), p.z()}}});
  }
  const std::string reply = http_request(service.http_port(), "POST", "/v1/correct", batch.dump());
  ASSERT_THAT(reply, StartsWith("200 "));
  const nlohmann::json results = nlohmann::json::parse(reply.substr(4))["results"];
  ASSERT_EQ(results.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string line = expected_reply(model, points[i]);
    if (results[i]["code"] != 0) {
      EXPECT_EQ(line, "(0,0,0,-3)\n");
      continue;
    }
    const auto& r = results[i]["robot_mm"];
    const std::string from_json =
        "(" + format_reply_number(r[0].get<double>()) + "," +
        format_reply_number(r[1].get<double>()) + "," + format_reply_number(r[2].get<double>()) +
        "," + format_reply_number(results[i]["predicted_sd_mm"].get<double>()) + ")\n";
    EXPECT_EQ(from_json, line);
  }
  const std::string single = http_request(
      service.http_port(), "POST", "/v1/correct",
      nlohmann::json{{"model", "cell"}, {"sensor_mm", {points[0].x(), points[0].y(), points[0].z()}}}.dump());
  EXPECT_THAT(single, StartsWith("200 "));
  EXPECT_THAT(single, HasSubstr(model.fiducials.empty() ? "x" : "\"sha256\""));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct", "{\"model\":"), StartsWith("400 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"x","sensor_mm":[1,2,3]})"),
              StartsWith("404 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"cell","sensor_mm":[1e5,2,3]})"),
              StartsWith("422 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct", std::string(2u << 20, ' ')),
              StartsWith("413 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           std::string(100, '[') + std::string(100, ']')),
              StartsWith("400 "));
  EXPECT_THAT(http_request(service.http_port(), "GET", "/nothing", ""), StartsWith("404 "));
  // An empty batch is refused, and the service answers on.
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"cell","points":[]})"),
              StartsWith("400 "));
  EXPECT_THAT(http_request(service.http_port(), "POST", "/v1/correct",
                           R"({"model":"nothing","points":[]})"),
              StartsWith("400 "));
  const std::string health = http_request(service.http_port(), "GET", "/v1/health", "");
  EXPECT_THAT(health, HasSubstr("\"method\":\"kriging\""));
  EXPECT_THAT(health, HasSubstr("\"sha256\":\""));
}

TEST(Service, ReloadSwapsAGoodFileAndKeepsServingOnABadOne) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kLinear, 7);
  std::vector<std::string> log;
  std::mutex log_mutex;
  Service service(local_options({{"cell", path}}),
                  [&](const std::string& m) { const std::lock_guard l(log_mutex); log.push_back(m); });
  service.start();
  LineClient c(service.line_port());
  const Eigen::Vector3d p = sensor_points_mm(1, 9)[0];
  const std::string before = c.ask(request_line("cell", p));
  const std::string sha_before = service.models().find("cell")->identity().sha256;

  const RegistrationModel other = write_model(path, InterpolationMethod::kLinear, 8);
  EXPECT_EQ(service.reload(true), 1);
  EXPECT_NE(service.models().find("cell")->identity().sha256, sha_before);
  EXPECT_EQ(c.ask(request_line("cell", p)), expected_reply(other, p));
  EXPECT_NE(c.ask(request_line("cell", p)), before);

  const std::string sha_good = service.models().find("cell")->identity().sha256;
  { std::ofstream(path) << "{ \"format\": \"vrreg-model\", truncated"; }
  EXPECT_EQ(service.reload(true), 0);
  EXPECT_EQ(service.models().find("cell")->identity().sha256, sha_good);
  EXPECT_EQ(c.ask(request_line("cell", p)), expected_reply(other, p));
  EXPECT_THAT(service.models().last_errors()[0], HasSubstr(path));
  const std::lock_guard l(log_mutex);
  EXPECT_THAT(log.back(), HasSubstr("reload failed, still serving"));
}

TEST(Service, AuditLogHasOneLinePerCorrectionAndRotates) {
  TempDir dir;
  write_model(dir.file("cell.json"), InterpolationMethod::kKriging);
  ServeOptions o = local_options({parse_model_source(dir.file("cell.json"))});
  o.audit.path = dir.file("audit.log");
  o.audit.max_bytes = 8192;
  o.audit.keep = 2;
  {
    Service service(o, nullptr);
    service.start();
    LineClient c(service.line_port());
    for (int i = 0; i < 200; ++i) c.ask("cell 1 2 3\n");
    c.ask(request_line("cell", sensor_points_mm(1, 2)[0]));
    service.stop();
  }
  std::size_t lines = 0;
  for (const std::string name : {"audit.log", "audit.log.1", "audit.log.2"}) {
    ASSERT_TRUE(std::filesystem::exists(dir.file(name))) << name;
    const std::string text = read_text(dir.file(name));
    for (std::size_t at = 0; (at = text.find('\n', at)) != std::string::npos; ++at) ++lines;
    EXPECT_LE(text.size(), 8192u + 4096u);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("audit.log.3")));
  EXPECT_GT(lines, 30u);
  const std::string last = read_text(dir.file("audit.log"));
  const std::string last_line = last.substr(last.rfind('\n', last.size() - 2) + 1);
  const nlohmann::json j = nlohmann::json::parse(last_line);
  EXPECT_EQ(j["model"], "cell");
  EXPECT_EQ(j["sha256"].get<std::string>().size(), 64u);
  EXPECT_TRUE(j.contains("robot_mm") || j.contains("reason"));
  EXPECT_THAT(j["client"].get<std::string>(), StartsWith("127.0.0.1:"));
}

TEST(Service, UrscriptSnippetBytesAreAnswered) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  const RegistrationModel model = io::read_model_json(path);
  ServeOptions o = local_options({{"cell", path}});
  o.token = "0123456789abcdef-secret";
  Service service(o, nullptr);
  service.start();
  SnippetOptions s;
  s.model = "cell";
  s.port = service.line_port();
  s.token = o.token;
  const std::string program = urscript_client(s);
  EXPECT_THAT(program, HasSubstr("def vrreg_correct(p_sensor_mm):"));
  EXPECT_THAT(program, HasSubstr("socket_read_ascii_float(n, \"vrreg\", 2)"));
  EXPECT_THAT(program, HasSubstr(", 4)\n  if reply[4] < 0:"));
  // The bytes URScript sends: socket_send_line appends "\r\n"? The manual says a newline; both
  // are answered. The program's vrreg_text writes each coordinate to 0.1 um, e.g. "412.5000".
  LineClient c(service.line_port());
  EXPECT_EQ(c.ask("auth 0123456789abcdef-secret\r\n"), "(1)\n");
  const Eigen::Vector3d p = sensor_points_mm(1, 4)[0];
  const std::string x = vrreg::testing::urscript_vrreg_text(static_cast<float>(p.x()), 10000);
  const std::string y = vrreg::testing::urscript_vrreg_text(static_cast<float>(p.y()), 10000);
  const std::string z = vrreg::testing::urscript_vrreg_text(static_cast<float>(p.z()), 10000);
  const std::string sent = urscript_request_line(s, x, y, z);
  EXPECT_EQ(sent, "cell " + x + " " + y + " " + z + "\n");
  const Eigen::Vector3d as_sent(std::stod(x), std::stod(y), std::stod(z));
  EXPECT_EQ(c.ask(sent), expected_reply(model, as_sent));
  EXPECT_EQ(c.ask("cell " + x + " " + y + " " + z + "\r\n"), expected_reply(model, as_sent));
}

TEST(Service, SixteenClientsGetTheirOwnAnswers) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  write_model(path, InterpolationMethod::kKriging);
  const RegistrationModel model = io::read_model_json(path);
  Service service(local_options({{"cell", path}}), nullptr);
  service.start();
  const std::vector<Eigen::Vector3d> points = sensor_points_mm(40, 11);
  std::vector<std::string> expected;
  for (const Eigen::Vector3d& p : points) expected.push_back(expected_reply(model, p));
  std::atomic<int> wrong{0};
  std::vector<std::thread> clients;
  for (int t = 0; t < 16; ++t) {
    clients.emplace_back([&, t] {
      LineClient c(service.line_port());
      for (int i = 0; i < 200; ++i) {
        const std::size_t k = static_cast<std::size_t>(t * 7 + i) % points.size();
        if (c.ask(request_line("cell", points[k])) != expected[k]) ++wrong;
      }
    });
  }
  for (std::thread& t : clients) t.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(service.stats().corrections, 16u * 200u);
}

}  // namespace
}  // namespace vrreg::serve::testing
