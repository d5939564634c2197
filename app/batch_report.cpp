#include "batch_report.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "common/error.h"
#include "common/markup_text.h"
#include "common/quote.h"

namespace facet {
namespace {

enum class CaseKind { Passed, Failure, Error, Skipped };

// One <testcase> element as written, with what the suite's counts need.
struct ReportCase {
  int line = 0;
  CaseKind kind = CaseKind::Passed;
  std::string element;  // "  <testcase .../>\n" or "  <testcase ...>...</testcase>\n"
};

std::string seconds3(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", seconds);
  return text;
}

CaseKind kindOf(const JobOutcome& o) {
  if (o.status == JobStatus::Failed || o.verdict == Verdict::FileError) return CaseKind::Error;
  if (o.verdict == Verdict::Fail || o.verdict == Verdict::DifferentSize) return CaseKind::Failure;
  if (o.status == JobStatus::Skipped) return CaseKind::Skipped;
  return CaseKind::Passed;
}

std::string caseName(const JobOutcome& o) { return "line " + std::to_string(o.line) + ": " + (o.output.empty() ? "(no output)" : o.output); }

ReportCase reportCase(const JobOutcome& o) {
  ReportCase c{o.line, kindOf(o), {}};
  std::string& e = c.element;
  e = "    <testcase classname=\"facet.batch\" name=\"" + markupEscaped(caseName(o)) + "\" time=\"" + seconds3(o.milliseconds / 1000.0) + "\"";
  std::string body;
  const std::string verdict(verdictName(o.verdict));
  if (c.kind == CaseKind::Error)
    body = "      <error message=\"" + markupEscaped(o.message) + "\" type=\"" + verdict + "\"/>\n";
  else if (c.kind == CaseKind::Failure)
    body = "      <failure message=\"" + markupEscaped(verdict + ": " + o.message) + "\" type=\"" + verdict + "\">" + markupEscaped(o.details) + "</failure>\n";
  else if (c.kind == CaseKind::Skipped)
    body = "      <skipped message=\"output up to date (--resume)\"/>\n";
  if (o.verdict == Verdict::Warn) body += "      <system-out>" + markupEscaped(o.details) + "</system-out>\n";
  e += body.empty() ? "/>\n" : ">\n" + body + "    </testcase>\n";
  return c;
}

// The whole report from its cases: the one place the suite's shape is written.
std::string suiteText(std::vector<ReportCase> cases, double seconds) {
  std::stable_sort(cases.begin(), cases.end(), [](const ReportCase& a, const ReportCase& b) { return a.line < b.line; });
  std::array<std::size_t, 4> counts{};
  for (const ReportCase& c : cases) ++counts[static_cast<std::size_t>(c.kind)];
  const std::string attributes = "tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(counts[1]) + "\" errors=\"" +
                                 std::to_string(counts[2]) + "\" skipped=\"" + std::to_string(counts[3]) + "\" time=\"" + seconds3(seconds) + "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"facet batch\" " + attributes + ">\n";
  out += "  <testsuite name=\"facet batch\" " + attributes + ">\n";
  for (const ReportCase& c : cases) out += c.element;
  out += "  </testsuite>\n</testsuites>\n";
  return out;
}

// The value of attribute `name` in the tag starting at `at`, or throws.
std::string attribute(const std::string& text, std::size_t at, const std::string& name, const std::string& file) {
  const std::size_t tagEnd = text.find('>', at);
  const std::size_t found = text.find(" " + name + "=\"", at);
  if (found == std::string::npos || found > tagEnd) throw Error(file + ": a tag without " + name + "=\"...\" at byte " + std::to_string(at));
  const std::size_t start = found + name.size() + 3;
  return text.substr(start, text.find('"', start) - start);
}

}  // namespace

int batchExitCode(const std::vector<JobOutcome>& outcomes) {
  Verdict worst = Verdict::Pass;
  for (const JobOutcome& o : outcomes) worst = std::max(worst, o.verdict);
  return static_cast<int>(worst);
}

std::string summaryText(const std::vector<JobOutcome>& outcomes, double seconds) {
  std::array<std::size_t, static_cast<std::size_t>(Verdict::Count)> perVerdict{};
  std::size_t skipped = 0, rendered = 0, compared = 0;
  for (const JobOutcome& o : outcomes) {
    ++perVerdict[static_cast<std::size_t>(o.verdict)];
    skipped += o.status == JobStatus::Skipped;
    rendered += o.status == JobStatus::Rendered;
    compared += o.compared;
  }
  std::string out;
  char line[160];
  for (const JobOutcome& o : outcomes)
    if (o.verdict != Verdict::Pass && o.verdict != Verdict::Warn) {
      std::snprintf(line, sizeof line, "%s line %d: ", std::string(verdictName(o.verdict)).c_str(), o.line);
      out += line + o.message + "\n";
    }
  std::snprintf(line, sizeof line, "%-16s %6s\n", "verdict", "jobs");
  out += line;
  for (std::size_t v = 0; v < perVerdict.size(); ++v) {
    std::snprintf(line, sizeof line, "%-16s %6zu\n", std::string(kVerdictNames[v]).c_str(), perVerdict[v]);
    out += line;
  }
  std::snprintf(line, sizeof line, "%zu jobs: %zu rendered, %zu skipped (up to date), %zu compared; %.2f s, %.1f jobs/s -> exit code %d\n",
                outcomes.size(), rendered, skipped, compared, seconds, seconds > 0.0 ? static_cast<double>(outcomes.size()) / seconds : 0.0,
                batchExitCode(outcomes));
  out += line;
  return out;
}

std::string junitReport(const std::vector<JobOutcome>& outcomes, double seconds) {
  std::vector<ReportCase> cases;
  for (const JobOutcome& o : outcomes) cases.push_back(reportCase(o));
  return suiteText(std::move(cases), seconds);
}

std::string mergeJunitReports(const std::vector<std::string>& reports, const std::vector<std::string>& names) {
  std::vector<ReportCase> cases;
  double seconds = 0.0;
  for (std::size_t r = 0; r < reports.size(); ++r) {
    const std::string& text = reports[r];
    const std::size_t suite = text.find("<testsuite name=\"facet batch\"");
    if (suite == std::string::npos) throw Error(names[r] + ": not a facet batch JUnit report (no <testsuite name=\"facet batch\">)");
    seconds += std::strtod(attribute(text, suite, "time", names[r]).c_str(), nullptr);
    for (std::size_t at = text.find("<testcase ", suite); at != std::string::npos; at = text.find("<testcase ", at + 1)) {
      const std::size_t tagEnd = text.find('>', at);
      if (tagEnd == std::string::npos) throw Error(names[r] + ": a testcase tag without its end at byte " + std::to_string(at));
      const bool empty = text[tagEnd - 1] == '/';
      const std::size_t close = empty ? tagEnd + 1 : text.find("</testcase>", tagEnd);
      if (close == std::string::npos) throw Error(names[r] + ": a testcase without </testcase> at byte " + std::to_string(at));
      const std::size_t end = empty ? close : close + std::string("</testcase>").size();
      ReportCase c;
      const std::string name = attribute(text, at, "name", names[r]);
      if (name.rfind("line ", 0) != 0) throw Error(names[r] + ": testcase " + quoteInput(name) + " is not named \"line N: ...\"");
      c.line = std::atoi(name.c_str() + 5);
      const std::string inner = text.substr(tagEnd, end - tagEnd);
      c.kind = inner.find("<error") != std::string::npos     ? CaseKind::Error
               : inner.find("<failure") != std::string::npos ? CaseKind::Failure
               : inner.find("<skipped") != std::string::npos ? CaseKind::Skipped
                                                             : CaseKind::Passed;
      c.element = "    " + text.substr(at, end - at) + "\n";
      cases.push_back(std::move(c));
    }
  }
  return suiteText(std::move(cases), seconds);
}

}  // namespace facet
