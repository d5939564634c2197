// facet batch: many frames from one job file (app/batch_jobs.h), rendered by
// worker threads that share loaded scenes and keep their renderers, with a
// summary, a JUnit report, --resume and --shard for many machines.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "batch_jobs.h"
#include "batch_report.h"
#include "batch_run.h"
#include "batch_shard.h"
#include "command_main.h"
#include "commands.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "compare/diff_case.h"
#include "exit_status.h"
#include "output_option.h"
#include "progress_bar.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

struct BatchCommandOptions {
  std::vector<std::string> inputs;  // the job file; with --merge, the reports
  int jobs = 0;                     // worker threads; 0: one per core
  std::string junit;
  bool resume = false;
  std::string shard;                // "I/N", when shardGiven
  bool shardGiven = false;          // --shard was on the command line (an empty value is refused, not "all jobs")
  bool dryRun = false;
  std::string merge;                // the merged report to write
};

constexpr const char* kFooter = R"(
JOBS.jsonl holds one JSON object a line (empty lines and lines starting
with # are skipped):
  {"scene": "model.glb", "set": ["shading=flat"], "size": "256x256",
   "backend": "cpu", "output": "out/model-flat.png"}
  {"scene": "builtin:cornell", "settings": {"shading": "gouraud"}, "backend": "gl",
   "output": "out/cornell.png", "expected": "golden/cornell.png", "fail": 0.0078, "failpercent": 0.1}
Keys: scene (a path or builtin:NAME; default: the default scene), set
(--set's key=value, in order, after settings), settings (a settings object),
size (WxH), backend (cpu, gl, ray, reference; default cpu), output (required),
expected (a PNG: compare as facet diff, with its fail, failpercent, warn,
warnpercent, hardfail, hardwarn as numbers). Relative paths are taken from
the job file's folder.

A bad job (a line that is not JSON, an unknown key, a missing scene, an
output that cannot be written) fails alone, named by its line; the others run.

Exit codes: the worst job's, as facet diff's:
  0 PASS (every frame written; compared ones within the warn thresholds)
  1 WARNING   2 FAILURE   3 different sizes
  4 a job could not be done (bad line, missing file, unwritable output), or
    the job file, a --junit report or a --merge input could not be read or written
  64 the command line is wrong (also --shard 0/0, 5/3)   70 internal error

--shard I/N runs job k (0-based, counting job lines only) when k mod N = I;
I counts from 0, as Kubernetes' JOB_COMPLETION_INDEX (start a Slurm array at
0: --array=0-N-1). --merge OUT.xml A.xml B.xml ... joins the shards' --junit
reports into the report of the whole run.)";

void printLine(const JobOutcome& o, std::size_t done, std::size_t total) {
  const std::string verdictText = o.status == JobStatus::Skipped && o.verdict == Verdict::Pass ? "SKIPPED" : std::string(verdictName(o.verdict));
  std::printf("[%zu/%zu] line %d %s %s %.0f ms%s%s\n", done, total, o.line, o.output.empty() ? "-" : o.output.c_str(), verdictText.c_str(),
              o.milliseconds, o.verdict == Verdict::Pass ? "" : ": ", o.verdict == Verdict::Pass ? "" : o.message.c_str());
  std::fflush(stdout);
}

int mergeReports(const BatchCommandOptions& options) {
  if (options.inputs.empty()) throw UsageError("--merge OUT.xml: name the reports to join after it");
  checkOutputFile(options.merge, options.inputs, MissingFolders::Refuse);
  std::vector<std::string> reports;
  for (const std::string& path : options.inputs) reports.push_back(readFile(path, kMaxReportFileBytes));
  writeFileAtomically(options.merge, mergeJunitReports(reports, options.inputs));
  std::printf("%zu reports merged into %s\n", reports.size(), options.merge.c_str());
  return 0;
}

int runJobs(const BatchCommandOptions& options) {
  if (options.inputs.size() != 1) throw UsageError("facet batch takes one job file (JOBS.jsonl), or --merge OUT.xml and reports");
  const Shard shard = options.shardGiven ? parseShard(options.shard) : Shard{};
  const std::string& path = options.inputs.front();
  if (!options.junit.empty()) checkOutputFile(options.junit, {path}, MissingFolders::Refuse);
  const std::vector<JobLine> all = readJobFile(path);
  // The report is none of the files a job reads or writes (a golden it compares against).
  if (!options.junit.empty()) {
    std::vector<std::string> files;
    for (const JobLine& j : all)
      if (j.job) files.insert(files.end(), {j.job->scene, j.job->expected, j.job->output});
    checkOutputFile(options.junit, files, MissingFolders::Refuse);
  }
  std::vector<JobLine> jobs;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (inShard(k, shard)) jobs.push_back(all[k]);
  if (options.dryRun) {
    for (const JobLine& j : jobs) std::printf("line %d %s\n", j.line, j.job ? j.output.c_str() : ("(bad job: " + j.problem + ")").c_str());
    return 0;
  }
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  BatchOptions run;
  run.jobFile = path;
  run.workers = options.jobs > 0 ? options.jobs : cores;
  run.cpuThreads = std::max(1, cores / run.workers);
  run.resume = options.resume;
  run.version = facetVersion();
  const bool lines = isatty(fileno(stdout)) != 1;  // a pipe or a file: one plain line per job
  ProgressBar bar("batch");                          // a terminal: the bar on stderr
  std::size_t done = 0, failed = 0;
  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&start]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const std::vector<JobOutcome> outcomes = runBatch(jobs, run, [&](const JobOutcome& o) {
    ++done;
    failed += o.verdict >= Verdict::Fail;
    if (lines) printLine(o, done, jobs.size());
    char detail[96];
    std::snprintf(detail, sizeof detail, "%zu/%zu done, %zu failed, %.1f jobs/s", done, jobs.size(), failed, static_cast<double>(done) / std::max(seconds(), 1e-3));
    bar.update(static_cast<double>(done) / static_cast<double>(std::max<std::size_t>(jobs.size(), 1)), detail);
  });
  bar.finish();
  const double wall = seconds();
  std::fputs(summaryText(outcomes, wall).c_str(), stdout);
  const int worst = batchExitCode(outcomes);
  if (!options.junit.empty()) {
    // A report that cannot be written is a file error, and does not hide a worse verdict of the jobs.
    try {
      writeFileAtomically(options.junit, junitReport(outcomes, wall));
    } catch (const Error& e) {
      printErrorLine(stderr, "", e.what());
      return std::max(worst, static_cast<int>(Verdict::FileError));
    }
    std::printf("JUnit report written to %s\n", options.junit.c_str());
  }
  return worst;
}

}  // namespace

Command addBatchCommand(CLI::App& app) {
  auto options = std::make_shared<BatchCommandOptions>();
  CLI::App* command = app.add_subcommand("batch", "Render (and compare) many frames from a job file, one JSON object a line, in parallel");
  command->add_option("jobs-file", options->inputs, "JOBS.jsonl; with --merge, the JUnit reports to join");
  command->add_option("--jobs", options->jobs, "jobs run at once (0: one per core)")->check(CLI::Range(0, kMaxParallelJobs));
  refuseEmptyName(command->add_option("--junit", options->junit, "write a JUnit XML report of the jobs to this file"));
  command->add_flag("--resume", options->resume, "skip jobs whose output exists, decodes, and was rendered from the same inputs (scene, settings, size, backend, facet version)");
  command->add_option("--shard", options->shard, "I/N: run only the I-th of N slices of the jobs (job k when k mod N = I; I from 0)")
      ->each([options](const std::string&) { options->shardGiven = true; });
  command->add_flag("--dry-run", options->dryRun, "list the jobs (of the shard) that would run, and render nothing");
  refuseEmptyName(command->add_option("--merge", options->merge, "OUT.xml: join the --junit reports given as arguments into one"));
  command->footer(kFooter);
  // A file the command itself reads or writes (the job file, --junit,
  // --merge's reports) that is missing, unreadable or unwritable is the
  // FILE ERROR verdict, 4, as in facet diff; the command line (64) and
  // internal errors (70) go on to main.
  return [options]() {
    try {
      return options->merge.empty() ? runJobs(*options) : mergeReports(*options);
    } catch (const UsageError&) {
      throw;
    } catch (const Error& e) {
      printErrorLine(stderr, "", e.what());
    }
    return static_cast<int>(Verdict::FileError);
  };
}

}  // namespace facet
