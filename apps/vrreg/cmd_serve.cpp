// SPDX-License-Identifier: Apache-2.0
// vrreg serve: the correction service (docs/serve.md). Loads fitted models once and answers
// correction requests from robot programs (line protocol) and cell software (HTTP/JSON).
#include <cstdio>
#include <mutex>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "serve/model_registry.hpp"
#include "serve/service.hpp"
#include "serve/served_model.hpp"
#include "serve/token.hpp"

namespace vrreg::cli {
namespace {

struct ServeArgs {
  std::vector<std::string> models;
  std::string listen;
  std::string http;
  bool allow_remote = false;
  std::string token_file;
  int threads = 0;
  int max_connections = 256;
  int max_http_connections = 256;
  int batch_threads = 0;
  double max_extrapolation = 1.0;
  std::size_t max_body_bytes = 1u << 20;
  std::size_t max_batch = 10000;
  double idle_timeout_s = 600.0;
  int reload_poll_ms = 1000;
  std::string audit_log;
  double audit_max_mb = 64.0;
  int audit_keep = 5;
};

void run_serve(const ServeArgs& args) {
  serve::ServeOptions options;
  for (const std::string& m : args.models) options.models.push_back(serve::parse_model_source(m));
  if (!args.listen.empty()) options.line = serve::parse_endpoint(args.listen);
  if (!args.http.empty()) options.http = serve::parse_endpoint(args.http);
  options.allow_remote = args.allow_remote;
  options.token = serve::read_token(args.token_file);
  options.threads = args.threads;
  options.max_connections = args.max_connections;
  options.max_http_connections = args.max_http_connections;
  options.batch_threads = args.batch_threads;
  options.max_extrapolation = args.max_extrapolation;
  options.max_body_bytes = args.max_body_bytes;
  options.max_batch = args.max_batch;
  options.idle_timeout_s = args.idle_timeout_s;
  options.reload_poll_ms = args.reload_poll_ms;
  options.audit.path = args.audit_log;
  options.audit.max_bytes = static_cast<std::size_t>(args.audit_max_mb * 1048576.0);
  options.audit.keep = args.audit_keep;
  static std::mutex log_mutex;
  const auto log = [](const std::string& message) {
    const std::lock_guard lock(log_mutex);
    std::fprintf(stderr, "%s vrreg serve: %s\n", serve::utc_now().c_str(), message.c_str());
    std::fflush(stderr);
  };
  const std::string line_address = options.line ? options.line->address : "";
  const std::string http_address = options.http ? options.http->address : "";
  serve::Service service(std::move(options), log);
  for (const auto& m : service.models().all()) {
    const serve::ModelIdentity& id = m->identity();
    log("model '" + id.name + "' from " + id.path + ": " + id.method + ", " +
        std::to_string(id.n_fiducials) + " fiducials, sha256 " + id.sha256);
  }
  if (service.line_port() != 0) {
    log("line protocol on " + line_address + ":" + std::to_string(service.line_port()));
  }
  if (service.http_port() != 0) {
    log("HTTP on " + http_address + ":" + std::to_string(service.http_port()));
  }
  log("ready (SIGHUP reloads the models, SIGINT or SIGTERM stops)");
  service.run_until_signalled();
  const serve::ServiceStats s = service.stats();
  log("stopped after " + std::to_string(s.corrections) + " corrections, " +
      std::to_string(s.refusals) + " refusals (" + std::to_string(s.malformed) + " malformed, " +
      std::to_string(s.unauthorized) + " unauthorized, " + std::to_string(s.limited) +
      " over a bound) on " + std::to_string(s.connections) + " connections");
}

void add_serve_command(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "serve",
      "Answer correction requests from robot programs (line protocol) and cell software "
      "(HTTP/JSON) with models fitted once (docs/serve.md)");
  CLI::Option* models =
      cmd->add_option("--model", args->models,
                      "a model JSON written by 'vrreg register -o', as FILE (named by its stem) or "
                      "NAME=FILE; repeat for several")
          ->required();
  declare_file_role(*cmd, models, FileRole::kInput, [args] {
    std::vector<std::string> paths;
    for (const std::string& m : args->models) paths.push_back(serve::parse_model_source(m).path);
    return paths;
  });
  not_a_file(*cmd, cmd->add_option("--listen", args->listen,
                                   "line protocol address, ADDRESS:PORT (e.g. 127.0.0.1:30401; "
                                   "port 0: any free)"));
  not_a_file(*cmd, cmd->add_option("--http", args->http, "HTTP/JSON address, ADDRESS:PORT"));
  cmd->add_flag("--allow-remote", args->allow_remote,
                "listen on addresses other than loopback (needs a token)");
  add_input_option(*cmd, "--token-file", args->token_file,
                   "file whose first line is the shared token clients must send (default: "
                   "$VRREG_SERVE_TOKEN; none on loopback)");
  cmd->add_option("--threads", args->threads, "threads answering (default: the cores)")
      ->check(CLI::Range(0, 256));
  cmd->add_option("--max-connections", args->max_connections,
                  "open line-protocol connections at most, the robots' own budget (HTTP "
                  "connections never take one); more are refused (default 256)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--max-http-connections", args->max_http_connections,
                  "open HTTP connections at most; more are refused with 503 (default 256)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--batch-threads", args->batch_threads,
                  "threads answering HTTP batches, apart from those answering the robots "
                  "(default: half the cores, at least 1)")
      ->check(CLI::Range(0, 256));
  cmd->add_option("--max-extrapolation", args->max_extrapolation,
                  "refuse (code 8) an 'extrapolate' request farther from the fiducials' bounding "
                  "box than this many times its diagonal (default 1; inf: no cap)");
  cmd->add_option("--max-body-bytes", args->max_body_bytes, "HTTP body size at most (default 1 MiB)");
  cmd->add_option("--max-batch", args->max_batch, "points in one HTTP batch at most (default 10000)");
  cmd->add_option("--idle-timeout-s", args->idle_timeout_s,
                  "close a connection silent this long (default 600)");
  cmd->add_option("--reload-poll-ms", args->reload_poll_ms,
                  "check the model files for changes this often; 0: on SIGHUP only (default 1000)");
  CLI::Option* audit_log =
      cmd->add_option("--audit-log", args->audit_log,
                      "append one JSON line per correction here (time, client, model sha256, "
                      "input, output, sd), rotated");
  // Rotation renames the log to LOG.1 ... LOG.KEEP and removes the oldest: all are written.
  declare_file_role(*cmd, audit_log, FileRole::kOutput, [args] {
    std::vector<std::string> paths;
    if (args->audit_log.empty()) return paths;
    paths.push_back(args->audit_log);
    for (int k = 1; k <= args->audit_keep; ++k)
      paths.push_back(args->audit_log + "." + std::to_string(k));
    return paths;
  });
  cmd->add_option("--audit-max-mb", args->audit_max_mb, "rotate the audit log at this size (default 64)")
      ->check(CLI::Range(0.004, 1e6));
  cmd->add_option("--audit-keep", args->audit_keep, "rotated audit logs kept (default 5)")
      ->check(CLI::Range(1, 1000));
  cmd->callback([args] { run_serve(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(38, add_serve_command);

}  // namespace vrreg::cli
