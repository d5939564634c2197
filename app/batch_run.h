#pragma once
// Running a job file's jobs: worker threads up to a limit, each with its own
// renderers (created on first use, reused for every later job of their
// backend: a GL context belongs to the thread that made it), sharing one
// cache of loaded scenes, so that each scene file is read once per run.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "batch_jobs.h"
#include "compare/diff_case.h"

namespace facet {

enum class JobStatus { Rendered, Skipped, Failed };

struct JobOutcome {
  int line = 0;
  std::string output;
  JobStatus status = JobStatus::Rendered;
  // As facet diff's: Pass for a frame written with no comparison asked; a
  // job that could not be done (bad line, missing scene, unwritable output)
  // is FileError, the worst, as diff's bad file.
  Verdict verdict = Verdict::Pass;
  bool compared = false;   // the job had "expected" and the images were compared
  std::string message;     // Failed: "JOBS.jsonl:LINE: problem"; compared: the diff's figures
  std::string details;     // compared: facet diff's block of figures for the case
  double milliseconds = 0.0;
};

struct BatchOptions {
  std::string jobFile;  // named in the lines of failed jobs
  int workers = 1;      // at least 1
  int cpuThreads = 1;   // each CPU renderer's and ray tracer's threads
  bool resume = false;  // skip jobs whose output holds the inputs hash of this run
  std::string version;  // facet's, part of the inputs hash
};

// Runs `jobs` (in that order; lines without a job fail at once) and calls
// `finished` with each outcome as it ends, one call at a time. Returns the
// outcomes in the order of `jobs`.
std::vector<JobOutcome> runBatch(const std::vector<JobLine>& jobs, const BatchOptions& options,
                                 const std::function<void(const JobOutcome&)>& finished);

// The keyword of the PNG tEXt chunk holding a batch output's inputs hash.
inline constexpr const char* kInputsKeyword = "facet-inputs";

}  // namespace facet
