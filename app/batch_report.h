#pragma once
// What `facet batch` reports at the end: the summary table on stdout, and a
// JUnit XML report (the format CI systems read: GitLab, Jenkins, GitHub
// actions' test reporters), which `facet batch --merge` joins across shards.
#include <string>
#include <vector>

#include "batch_run.h"

namespace facet {

// The exit code of the run: the worst job's verdict, as facet diff's (0 when
// there are no jobs).
int batchExitCode(const std::vector<JobOutcome>& outcomes);

// The table of counts per verdict, the failed jobs' lines, the wall time and
// the rate; ends with a newline.
std::string summaryText(const std::vector<JobOutcome>& outcomes, double seconds);

// A JUnit report: one testsuite "facet batch", a testcase per job named
// "line N: OUTPUT" in line order; <failure> for FAILURE and DIFFERENT SIZES
// (the diff's figures), <error> for a job that could not be done, <skipped>
// for an output --resume found up to date. A WARNING passes, its figures in
// <system-out>.
std::string junitReport(const std::vector<JobOutcome>& outcomes, double seconds);

// Joins reports junitReport wrote (one per shard) into the report of the
// whole run: counts and times summed, testcases in line order. `names` name
// the reports in errors; throws facet::Error for a file that is not such a report.
std::string mergeJunitReports(const std::vector<std::string>& reports, const std::vector<std::string>& names);

}  // namespace facet
