// SPDX-License-Identifier: Apache-2.0
// The service under hostile load, compressed: good clients checking every answer, reloads between
// two model files, clients that disconnect mid-request, a client that never reads its replies,
// and garbage; no wrong answer, no lost request, no memory growth. VRREG_SOAK_SECONDS lengthens it
// (default 6 s; docs/serve.md gives the long form).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <thread>
#include <unistd.h>

#include "serve/line_protocol.hpp"
#include "serve/service.hpp"
#include "serve_test_support.hpp"
#include "vrreg/core/format.hpp"
#include "vrreg/core/units.hpp"

namespace vrreg::serve::testing {
namespace {

double soak_seconds() {
  const char* s = std::getenv("VRREG_SOAK_SECONDS");
  return s ? std::max(1.0, std::atof(s)) : 6.0;
}

long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0;
  long resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

TEST(ServiceSoak, NoWrongAnswerNoLostRequestNoGrowthAcrossReloadsAndHostileClients) {
  TempDir dir;
  const std::string path = dir.file("cell.json");
  const std::string a_path = dir.file("a.json");
  const std::string b_path = dir.file("b.json");
  const RegistrationModel a = write_model(a_path, InterpolationMethod::kKriging, 7);
  const RegistrationModel b = write_model(b_path, InterpolationMethod::kKriging, 8);
  std::filesystem::copy_file(a_path, path);

  // Points inside the cell: both models correct them, with different numbers.
  const MeasuredPoints cell = lattice_cell();
  std::vector<std::string> requests;
  std::vector<std::string> from_a;
  std::vector<std::string> from_b;
  for (Eigen::Index j = 0; j + 1 < cell.size(); j += 3) {
    const Eigen::Vector3d p = 500.0 * (cell.sensor_m.col(j) + cell.sensor_m.col(j + 1));
    requests.push_back("cell " + format_general(p.x(), 17) + " " + format_general(p.y(), 17) + " " +
                       format_general(p.z(), 17) + "\n");
    const Eigen::Vector3d as_sent(std::stod(format_general(p.x(), 17)),
                                  std::stod(format_general(p.y(), 17)),
                                  std::stod(format_general(p.z(), 17)));
    from_a.push_back(expected_reply(a, as_sent));
    from_b.push_back(expected_reply(b, as_sent));
    ASSERT_NE(from_a.back(), from_b.back());
  }

  ServeOptions o;
  o.models = {{"cell", path}};
  o.line = Endpoint{"127.0.0.1", 0};
  o.threads = 2;
  o.reload_poll_ms = 0;
  o.io_timeout_s = 0.5;
  o.audit.path = dir.file("audit.log");
  o.audit.max_bytes = 1u << 20;
  o.audit.keep = 2;
  Service service(o, nullptr);
  service.start();
  const unsigned short port = service.line_port();
  const auto end = std::chrono::steady_clock::now() +
                   std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double>(soak_seconds()));
  // The run ends when both the time is up and the 100 reloads are done (slower under sanitizers).
  std::atomic<bool> reloaded_all{false};
  const auto running = [&] { return !reloaded_all || std::chrono::steady_clock::now() < end; };
  std::atomic<long> answered{0};
  std::atomic<long> wrong{0};
  std::atomic<long> lost{0};
  std::atomic<int> reloads{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 6; ++t) {  // good clients: every answer is model A's or model B's
    threads.emplace_back([&, t] {
      LineClient c(port);
      for (std::size_t i = static_cast<std::size_t>(t); running(); ++i) {
        const std::size_t k = i % requests.size();
        const std::string r = c.ask(requests[k]);
        if (r.empty()) {
          ++lost;
          return;
        }
        if (r != from_a[k] && r != from_b[k]) ++wrong;
        ++answered;
      }
    });
  }
  threads.emplace_back([&] {  // 100 reloads, alternating the file's content, spread over the run
    const double step = soak_seconds() / 110.0;
    for (int i = 0; i < 100; ++i) {
      std::filesystem::copy_file(i % 2 == 0 ? b_path : a_path, path + ".new",
                                 std::filesystem::copy_options::overwrite_existing);
      std::filesystem::rename(path + ".new", path);
      reloads += service.reload(false);
      std::this_thread::sleep_for(std::chrono::duration<double>(step));
    }
    reloaded_all = true;
  });
  threads.emplace_back([&] {  // disconnects mid-request and garbage
    std::mt19937 rng(5);
    while (running()) {
      LineClient c(port);
      std::string junk(static_cast<std::size_t>(rng() % 3000), '\0');
      for (char& ch : junk) ch = static_cast<char>(rng());
      c.send("cell 1 2");  // half a request, then gone
      if (rng() % 2 == 0) c.send(junk);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  threads.emplace_back([&] {  // a client that never reads: dropped after the io timeout
    while (running()) {
      LineClient c(port);
      boost::system::error_code ec;
      std::string many;
      for (int i = 0; i < 20000; ++i) many += requests[0];
      boost::asio::write(c.socket(), boost::asio::buffer(many), ec);
      std::this_thread::sleep_for(std::chrono::milliseconds(600));
    }
  });
  std::this_thread::sleep_for(std::chrono::duration<double>(soak_seconds() / 4));
  const long rss_early = resident_kib();
  for (std::thread& t : threads) t.join();
  const long rss_late = resident_kib();
  // Connections end when their clients go; the one that never read is dropped by the watchdog.
  for (int i = 0; i < 300 && service.stats().open_connections > 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(service.stats().open_connections, 0);
  service.stop();

  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(lost.load(), 0);
  EXPECT_GT(answered.load(), 1000);
  EXPECT_EQ(reloads.load(), 100);  // every reload of a changed file swapped the model in
  // Growth over the last three quarters of the run: models swapped out and connections closed
  // are freed. (Allocator caches and the audit buffer stay well within this.)
  // Under the sanitizers freed memory sits in ASan's quarantine: LeakSanitizer checks instead.
  if (std::getenv("VRREG_SANITIZED") == nullptr) {
    EXPECT_LT(rss_late - rss_early, 16 * 1024) << rss_early << " KiB -> " << rss_late << " KiB";
  }
}

}  // namespace
}  // namespace vrreg::serve::testing
