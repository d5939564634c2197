// The JUnit report: counts, one testcase per job, and shards merged into the whole run's report.
#include <doctest/doctest.h>

#include <regex>

#include "batch_report.h"

namespace facet {
namespace {

std::vector<JobOutcome> outcomes() {
  std::vector<JobOutcome> all(6);
  for (int k = 0; k < 6; ++k) all[k].line = 2 * k + 1, all[k].output = "out/" + std::to_string(k) + ".png", all[k].milliseconds = 10.0 * k;
  all[1].verdict = Verdict::Fail, all[1].compared = true, all[1].message = "3 pixels <over>", all[1].details = "a & b";
  all[2].status = JobStatus::Failed, all[2].verdict = Verdict::FileError, all[2].message = "jobs:5: unknown key 'x'";
  all[3].status = JobStatus::Skipped;
  all[4].verdict = Verdict::Warn, all[4].compared = true, all[4].details = "warned";
  return all;
}

std::string withoutTimes(const std::string& xml) { return std::regex_replace(xml, std::regex(" time=\"[0-9.]+\""), ""); }

}  // namespace

TEST_CASE("a JUnit report counts failures, errors and skipped jobs and escapes text") {
  const std::string xml = junitReport(outcomes(), 1.5);
  CHECK(xml.find("<testsuite name=\"facet batch\" tests=\"6\" failures=\"1\" errors=\"1\" skipped=\"1\" time=\"1.500\">") != std::string::npos);
  CHECK(xml.find("name=\"line 3: out/1.png\"") != std::string::npos);
  CHECK(xml.find("message=\"FAILURE: 3 pixels &lt;over&gt;\"") != std::string::npos);
  CHECK(xml.find(">a &amp; b</failure>") != std::string::npos);
  CHECK(xml.find("<error message=\"jobs:5: unknown key &#39;x&#39;\" type=\"FILE ERROR\"/>") != std::string::npos);
  CHECK(xml.find("<system-out>warned</system-out>") != std::string::npos);
  CHECK(batchExitCode(outcomes()) == 4);
}

TEST_CASE("shards' reports merge into the whole run's report, times apart") {
  const std::vector<JobOutcome> all = outcomes();
  for (const std::size_t n : {1u, 2u, 3u, 7u}) {
    std::vector<std::string> reports, names;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<JobOutcome> shard;
      for (std::size_t k = i; k < all.size(); k += n) shard.push_back(all[k]);
      reports.push_back(junitReport(shard, 1.0));
      names.push_back("shard" + std::to_string(i));
    }
    CHECK(withoutTimes(mergeJunitReports(reports, names)) == withoutTimes(junitReport(all, 1.0)));
  }
  CHECK_THROWS(mergeJunitReports({"<testsuites/>"}, {"x.xml"}));
}

}  // namespace facet
