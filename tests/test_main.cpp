// The doctest runner of every test binary. A run whose filters select no
// test case fails: ctest runs each case as its own entry
// (doctest_discover_tests), and an entry whose name the filter no longer
// matches (a renamed case, a name doctest splits) must not pass silently.
// A run of one case that passes but skipped a check (skipped.h) exits
// kSkippedExitCode, which ctest reports as skipped.
#define DOCTEST_CONFIG_IMPLEMENT
#include <cstdio>

#include <doctest/doctest.h>

#include "skipped.h"

namespace {

bool anySkipped = false;  // a check was skipped (facet::test::skipped)

// doctest hands listeners the run's statistics and nothing back to main; a
// file-local counter is how the count gets out.
unsigned casesRun = 0;

struct CaseCounter final : doctest::IReporter {
  explicit CaseCounter(const doctest::ContextOptions&) {}
  void report_query(const doctest::QueryData&) override {}
  void test_run_start() override {}
  void test_run_end(const doctest::TestRunStats& stats) override { casesRun = stats.numTestCasesPassingFilters; }
  void test_case_start(const doctest::TestCaseData&) override {}
  void test_case_reenter(const doctest::TestCaseData&) override {}
  void test_case_end(const doctest::CurrentTestCaseStats&) override {}
  void test_case_exception(const doctest::TestCaseException&) override {}
  void subcase_start(const doctest::SubcaseSignature&) override {}
  void subcase_end() override {}
  void log_assert(const doctest::AssertData&) override {}
  void log_message(const doctest::MessageData&) override {}
  void test_case_skipped(const doctest::TestCaseData&) override {}
};

REGISTER_LISTENER("case_counter", 1, CaseCounter);

}  // namespace

void facet::test::skipped(const std::string& what) {
  MESSAGE("skipped: " << what);
  anySkipped = true;
}

int main(int argc, char** argv) {
  doctest::Context context(argc, argv);
  const int result = context.run();
  if (context.shouldExit()) return result;  // --help, --list-test-cases, ...
  if (casesRun == 0) {
    std::fprintf(stderr, "doctest: the filters select no test case; a run that tests nothing fails\n");
    return 1;
  }
  if (result == 0 && anySkipped && casesRun == 1) return facet::test::kSkippedExitCode;
  return result;
}
