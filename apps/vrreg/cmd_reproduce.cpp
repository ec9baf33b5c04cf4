// SPDX-License-Identifier: Apache-2.0
// vrreg reproduce: the paper's experiments end to end on the simulated test beds. Simulates UR5
// datasets A1, A2, B and the KUKA LWR 4+ grid for one seed (or K seeds, in parallel), processes
// them as sections 4.3 and 4.4 do, prints Tables 1-2 and the Figure 7-8 data beside the paper's
// and checks the paper's findings; writes every figure's data as CSV and reproduce.json.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "cli_support.hpp"
#include "command_registry.hpp"
#include "progress_bar.hpp"
#include "report_cli.hpp"
#include "vrreg/core/check.hpp"
#include "vrreg/core/progress.hpp"
#include "vrreg/core/random.hpp"
#include "vrreg/experiments/beyond_report.hpp"
#include "vrreg/experiments/reproduction_csv.hpp"
#include "vrreg/experiments/reproduction_json.hpp"
#include "vrreg/experiments/reproduction_text.hpp"
#include "vrreg/io/atomic_write.hpp"
#include "vrreg/io/file_error.hpp"

namespace vrreg::cli {
namespace {

struct ReproduceArgs {
  std::uint64_t seed = 1;
  int seeds = 1;
  std::string out = "out/reproduce";
  std::string only;
  bool json = false;
  bool quiet = false;
  bool check = false;
  bool no_report = false;
  bool beyond = false;
};

// Every output file of --out: all of them, each whole, or none.
std::vector<std::string> write_outputs(const std::string& dir,
                                       const std::vector<experiments::Reproduction>& runs,
                                       const experiments::CellTable& cells,
                                       const nlohmann::json& doc) {
  namespace ex = experiments;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw io::FileError(dir, 0, "cannot create the output directory: " + ec.message());
  const ex::Reproduction& first = runs.front();
  std::vector<std::pair<std::string, std::string>> files = {
      {"table1.csv", ex::table1_csv(cells)},
      {"figure7_8.csv", ex::figure7_8_csv(cells)},
      {"figure10_targets.csv", ex::figure10_targets_csv(first)},
      {"figure11_delta_tre.csv", ex::figure11_delta_tre_csv(first)},
      {"table2.csv", ex::table2_csv(cells)},
      {"histograms_l.csv", ex::histograms_l_csv(first)},
      {"tre_per_target.csv", ex::tre_per_target_csv(first)},
      {"reproduce.json", doc.dump(2) + "\n"},
  };
  if (!first.beyond.empty()) files.emplace_back("beyond.csv", ex::beyond_csv(cells, first.beyond));
  std::vector<std::string> names;
  std::vector<io::OutputFile> outputs;
  for (auto& [name, text] : files) {
    outputs.push_back({(std::filesystem::path(dir) / name).string(), std::move(text)});
    names.push_back(name);
  }
  io::write_files_atomically(outputs);
  return names;
}

// The HTML report of `dir` (as `vrreg report --reproduce DIR` writes it); without the charting
// library it says why on stderr and the figure data stand alone.
std::optional<std::string> write_report(const std::string& dir, const nlohmann::json& doc) {
  const std::string path = (std::filesystem::path(dir) / "report.html").string();
  try {
    write_reproduce_report(doc, (std::filesystem::path(dir) / "reproduce.json").string(), "", path);
  } catch (const InputError& e) {
    std::fprintf(stderr, "reproduce: no HTML report: %s\n", e.what());
    return std::nullopt;
  }
  return path;
}

void run_reproduce(const ReproduceArgs& args) {
  namespace ex = experiments;
  VRREG_THROW_UNLESS(args.seeds >= 1 && args.seeds <= 1000,
                     "--seeds must be between 1 and 1000, got " << args.seeds);
  check_seed_run(args.seed, static_cast<std::uint64_t>(args.seeds), "--seed, --seeds");
  std::vector<std::uint64_t> seeds;
  for (int k = 0; k < args.seeds; ++k) seeds.push_back(args.seed + static_cast<std::uint64_t>(k));
  ex::ReproductionOptions options;
  options.ur5 = args.only.empty() || args.only == "ur5";
  options.lwr4 = args.only.empty() || args.only == "lwr4";
  options.beyond = args.beyond;

  const auto start = std::chrono::steady_clock::now();
  ProgressBar progress(args.seeds * ex::reproduction_steps(options), !args.quiet);
  // Its own bar counts the runs: the library's stages (each fit) would fight it for the line.
  const ProgressSink stages = set_progress_sink({});
  const std::vector<ex::Reproduction> runs =
      ex::run_reproductions(seeds, options, [&progress] { progress.step(); });
  set_progress_sink(stages);
  progress.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::vector<ex::Cell>> cells;
  std::vector<std::vector<ex::Finding>> findings;
  for (const ex::Reproduction& r : runs) {
    cells.push_back(ex::reproduction_cells(r));
    findings.push_back(ex::evaluate_findings(r));
  }
  const ex::CellTable table = ex::summarize_cells(cells);
  const nlohmann::json doc = ex::reproduction_json(runs);
  const std::vector<std::string> written =
      args.out.empty() ? std::vector<std::string>{} : write_outputs(args.out, runs, table, doc);
  const std::optional<std::string> report =
      args.out.empty() || args.no_report ? std::nullopt : write_report(args.out, doc);

  bool all_met = true;
  const std::vector<ex::FindingRate> rates = ex::finding_rates(findings);
  for (const ex::FindingRate& r : rates) all_met = all_met && (r.n_evaluated == 0 || r.accepted());

  if (args.json) {
    print_json(doc);
  } else {
    if (args.seeds == 1) {
      std::printf("vrreg reproduce: seed %llu\n", static_cast<unsigned long long>(args.seed));
    } else {
      std::printf("vrreg reproduce: seeds %llu-%llu (%d seeds; mean ± sd over them)\n",
                  static_cast<unsigned long long>(seeds.front()),
                  static_cast<unsigned long long>(seeds.back()), args.seeds);
    }
    std::printf(
        "Simulated UR5 (datasets A1, A2, B) and KUKA LWR 4+ (grid in 4 arm configurations), "
        "processed as in the paper's\nsections 4.3-4.4 (docs/reproduction.md). The paper's "
        "numbers are beside ours.\n\n");
    std::fputs(ex::format_reproduction_tables(table).c_str(), stdout);
    std::fputs(ex::format_beyond_tables(table, runs.front().beyond).c_str(), stdout);
    std::fputs(args.seeds == 1 ? ex::format_findings(findings.front()).c_str()
                               : ex::format_finding_rates(rates, findings.front()).c_str(),
               stdout);
    if (!written.empty()) {
      std::printf("\nFigure data written to %s/:", args.out.c_str());
      for (const std::string& name : written) std::printf(" %s", name.c_str());
      std::printf("\n");
    }
    if (report) std::printf("HTML report (opens offline in a browser): %s\n", report->c_str());
  }
  std::fflush(stdout);
  if (!args.quiet) {
    std::fprintf(stderr, "reproduce: %d seed%s in %.1f s\n", args.seeds, args.seeds == 1 ? "" : "s",
                 seconds);
  }
  VRREG_THROW_UNLESS(all_met || !args.check, "reproduce: some of the paper's findings are not met");
}

void add_reproduce_command(CLI::App& app) {
  auto args = std::make_shared<ReproduceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reproduce",
      "reproduce the paper on the simulated test beds: Tables 1-2 and the Figure 7-8 data beside "
      "the paper's, the paper's findings checked, every figure's data as CSV");
  add_seed_option(*cmd, "--seed", args->seed,
                  "first seed: draws the robots, the noise and Strategy 3's "
                  "corner configurations")
      ->capture_default_str();
  cmd->add_option("--seeds", args->seeds,
                  "number of seeds K: runs seeds N..N+K-1 on all cores and prints mean ± sd of "
                  "every cell and how often each finding holds")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  CLI::Option* out =
      cmd->add_option("--out", args->out,
                      "directory for table1.csv, figure7_8.csv, figure10_targets.csv, "
                      "figure11_delta_tre.csv, table2.csv, histograms_l.csv, tre_per_target.csv "
                      "and reproduce.json (empty: write nothing)")
          ->capture_default_str();
  declare_file_role(*cmd, out, FileRole::kOutputDirectory,
                    [args] { return std::vector<std::string>{args->out}; });
  cmd->add_flag("--no-report", args->no_report,
                "do not write report.html (the charts of 'vrreg report --reproduce DIR') to --out");
  cmd->add_flag("--beyond", args->beyond,
                "also beyond the paper: RRBC beside the field models (linear, trilinear, rbf, "
                "kriging, joint, auto) on A1, A2, B, fewer fiducials and the KUKA, with the noise "
                "floor and the predicted-sd calibration; writes beyond.csv (slower)");
  cmd->add_flag("--json", args->json, "print reproduce.json instead of the tables");
  cmd->add_flag("--quiet", args->quiet, "no progress bar or timing on stderr");
  cmd->add_flag("--check", args->check,
                "exit with status 1 when a finding is not met (on >= 80 % of the seeds)");
  not_a_file(*cmd, cmd->add_option("--only", args->only,
                                   "run one test bed only (ur5: Table 1, Fig. 7-11; lwr4: "
                                   "Table 2)")
                       ->check(CLI::IsMember({"ur5", "lwr4"}))
                       ->group(""));
  cmd->callback([args] { run_reproduce(*args); });
}

}  // namespace

VRREG_REGISTER_COMMAND(5, add_reproduce_command);

}  // namespace vrreg::cli
