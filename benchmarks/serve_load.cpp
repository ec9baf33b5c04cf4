// SPDX-License-Identifier: Apache-2.0
// vrreg_serve_load: a bounded load generator for correction services speaking vrreg's line
// protocol or its HTTP/JSON (vrreg serve, or the Python peer python/benchmarks/serve_peer.py).
// N clients, each on its own connection, send one request, wait for its reply, and repeat for a
// fixed time; prints requests per second and the latency percentiles, and counts replies that
// differ from the expected ones (--expect) or are refusals.
//
//   vrreg_serve_load --line 127.0.0.1:30401 --model cell --points pts.txt --clients 16 --seconds 5
#include <utility>  // before Boost.Asio 1.74, whose awaitable.hpp uses std::exchange

#include <algorithm>
#include <atomic>
#include <boost/asio.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

struct Args {
  std::string address = "127.0.0.1";
  unsigned short port = 0;
  bool http = false;
  std::string model = "cell";
  std::string points_file;
  std::string expect_file;
  int clients = 16;
  double seconds = 5.0;
};

[[noreturn]] void usage(const char* why) {
  std::fprintf(stderr,
               "vrreg_serve_load: %s\nusage: vrreg_serve_load (--line|--http) ADDRESS:PORT --model NAME "
               "--points FILE [--expect FILE] [--clients N] [--seconds S]\n",
               why);
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (i + 1 >= argc) usage(("missing value after " + key).c_str());
    const std::string value = argv[++i];
    if (key == "--line" || key == "--http") {
      a.http = key == "--http";
      const std::size_t colon = value.rfind(':');
      if (colon == std::string::npos) usage("expected ADDRESS:PORT");
      a.address = value.substr(0, colon);
      a.port = static_cast<unsigned short>(std::stoi(value.substr(colon + 1)));
    } else if (key == "--model") {
      a.model = value;
    } else if (key == "--points") {
      a.points_file = value;
    } else if (key == "--expect") {
      a.expect_file = value;
    } else if (key == "--clients") {
      a.clients = std::stoi(value);
    } else if (key == "--seconds") {
      a.seconds = std::stod(value);
    } else {
      usage(("unknown option " + key).c_str());
    }
  }
  if (a.port == 0 || a.points_file.empty()) usage("--line or --http and --points are required");
  if (a.clients < 1 || a.clients > 1024 || !(a.seconds > 0 && a.seconds <= 3600)) usage("bad bounds");
  return a;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  if (!in) usage(("cannot open " + path).c_str());
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

struct ClientResult {
  std::vector<double> latency_us;
  long wrong = 0;
  long refused = 0;
  std::string error;
};

std::string http_body_of(const std::string& response) {
  const std::size_t at = response.find("\r\n\r\n");
  return at == std::string::npos ? std::string() : response.substr(at + 4);
}

void run_client(const Args& args, const std::vector<std::string>& requests,
                const std::vector<std::string>& expected, int index, Clock::time_point end,
                ClientResult& out) {
  try {
    asio::io_context io;
    tcp::socket socket(io);
    socket.connect({asio::ip::make_address(args.address), args.port});
    socket.set_option(tcp::no_delay(true));
    std::string buffer;
    std::size_t k = static_cast<std::size_t>(index) * 7919 % requests.size();
    while (Clock::now() < end) {
      const Clock::time_point t0 = Clock::now();
      std::string reply;
      if (!args.http) {
        asio::write(socket, asio::buffer(requests[k]));
        const std::size_t n = asio::read_until(socket, asio::dynamic_buffer(buffer), '\n');
        reply = buffer.substr(0, n);
        buffer.erase(0, n);
        if (reply.rfind("(0,0,0,-", 0) == 0) ++out.refused;
      } else {
        asio::write(socket, asio::buffer(requests[k]));
        const std::size_t head = asio::read_until(socket, asio::dynamic_buffer(buffer), "\r\n\r\n");
        const std::string headers = buffer.substr(0, head);
        const std::size_t cl = headers.find("Content-Length: ");
        const std::size_t length = cl == std::string::npos ? 0 : std::stoul(headers.substr(cl + 16));
        if (buffer.size() < head + length) {
          asio::read(socket, asio::dynamic_buffer(buffer), asio::transfer_exactly(head + length - buffer.size()));
        }
        reply = buffer.substr(0, head + length);
        buffer.erase(0, head + length);
        if (reply.rfind("HTTP/1.1 200", 0) != 0) ++out.refused;
        reply = http_body_of(reply);
      }
      out.latency_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
      if (!expected.empty() && reply != expected[k]) ++out.wrong;
      k = (k + 1) % requests.size();
    }
  } catch (const std::exception& e) {
    out.error = e.what();
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const std::vector<std::string> points = lines_of(args.points_file);
  if (points.empty()) usage("no points");
  std::vector<std::string> requests;
  for (const std::string& p : points) {
    if (!args.http) {
      requests.push_back(args.model + " " + p + "\n");
    } else {
      std::string xyz = p;
      std::replace(xyz.begin(), xyz.end(), ' ', ',');
      const std::string body = "{\"model\":\"" + args.model + "\",\"sensor_mm\":[" + xyz + "]}";
      requests.push_back("POST /v1/correct HTTP/1.1\r\nHost: vrreg\r\nContent-Type: application/json\r\n"
                         "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
    }
  }
  std::vector<std::string> expected;
  if (!args.expect_file.empty()) {
    for (std::string& e : lines_of(args.expect_file)) expected.push_back(args.http ? e : e + "\n");
    if (expected.size() != points.size()) usage("--expect needs one line per point");
  }
  std::vector<ClientResult> results(static_cast<std::size_t>(args.clients));
  std::vector<std::thread> threads;
  const Clock::time_point start = Clock::now();
  const Clock::time_point end = start + std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(args.seconds));
  for (int c = 0; c < args.clients; ++c) {
    threads.emplace_back(run_client, std::cref(args), std::cref(requests), std::cref(expected), c, end,
                         std::ref(results[static_cast<std::size_t>(c)]));
  }
  for (std::thread& t : threads) t.join();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  std::vector<double> all;
  long wrong = 0;
  long refused = 0;
  int failed = 0;
  for (const ClientResult& r : results) {
    all.insert(all.end(), r.latency_us.begin(), r.latency_us.end());
    wrong += r.wrong;
    refused += r.refused;
    if (!r.error.empty()) {
      ++failed;
      std::fprintf(stderr, "client error: %s\n", r.error.c_str());
    }
  }
  std::sort(all.begin(), all.end());
  const auto pct = [&](double p) {
    return all.empty() ? 0.0 : all[std::min(all.size() - 1, static_cast<std::size_t>(p * double(all.size())))];
  };
  std::printf(
      "{\"protocol\":\"%s\",\"clients\":%d,\"seconds\":%.2f,\"requests\":%zu,\"per_second\":%.0f,"
      "\"p50_us\":%.1f,\"p99_us\":%.1f,\"max_us\":%.1f,\"wrong\":%ld,\"refused\":%ld,"
      "\"failed_clients\":%d}\n",
      args.http ? "http" : "line", args.clients, elapsed, all.size(), double(all.size()) / elapsed,
      pct(0.50), pct(0.99), all.empty() ? 0.0 : all.back(), wrong, refused, failed);
  return (wrong > 0 || failed > 0) ? 1 : 0;
}
