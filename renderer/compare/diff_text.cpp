#include "compare/diff_text.h"

#include <array>
#include <iterator>
#include <sstream>

#include "compare/diff_format.h"

namespace facet {
namespace {

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

void writeFigures(std::ostringstream& out, const DiffResult& r, const DiffThresholds& t) {
  out << "  max difference   ";
  for (std::size_t c = 0; c < 4; ++c) out << " " << kChannelNames[c] << " " << r.channels[c].max;
  out << "   (8-bit levels)\n  mean difference  ";
  for (std::size_t c = 0; c < 4; ++c) out << " " << kChannelNames[c] << " " << formatNumber(r.channels[c].mean);
  // idiff's figures in idiff's words and units, to compare with its output.
  out << "\n  mean error " << formatIdiffNumber(r.meanError / 255.0) << ", RMS error " << formatIdiffNumber(r.rmse / 255.0) << ", PSNR "
      << formatIdiffNumber(r.psnr) << " dB   (" << formatChannels(r.storedChannels) << "; fractions of full scale, as idiff)\n";
  out << "  max error " << formatIdiffNumber(r.worst.difference / 255.0);
  if (r.worst.x >= 0)
    out << " (" << r.worst.difference << (r.worst.difference == 1 ? " level" : " levels") << ") at "
        << formatPosition(r.worst.x, r.worst.y, r.height) << " " << formatChannel(r.worst.channel, r.storedChannels) << ": expected "
        << formatColor(r.worst.expected) << ", actual " << formatColor(r.worst.actual);
  out << "\n";
  out << "  over fail threshold " << formatThreshold(t.failThreshold) << ": " << formatPixels(r.failingPixels) << " ("
      << formatNumber(r.failingPercent) << "%), allowed " << formatAllowed(t.failPercent, t.allowFailures) << "\n";
  out << "  over warn threshold " << formatThreshold(t.warnThreshold) << ": " << formatPixels(r.warningPixels) << " ("
      << formatNumber(r.warningPercent) << "%), allowed " << formatAllowed(t.warnPercent) << "\n";
  if (t.hardFail != kNoLimit || t.hardWarn != kNoLimit)
    out << "  hard limits: fail " << formatThreshold(t.hardFail) << ", warn " << formatThreshold(t.hardWarn) << "; largest difference "
        << r.maxDifference << "\n";
  out << "  differing pixels " << r.differingPixels << ", in " << formatBox(r.differing, r.height) << "   (y from the top row)\n";
  out << "  failing pixels   " << r.failingPixels << ", in " << formatBox(r.failing, r.height) << "\n";
}

}  // namespace

std::string caseText(const DiffCase& c, const DiffThresholds& thresholds) {
  std::ostringstream out;
  out << c.name << ": " << verdictName(c.verdict) << "\n";
  if (c.result) {
    out << "  expected " << c.expectedPath << "\n  actual   " << c.actualPath << "\n";
    writeFigures(out, *c.result, thresholds);
  } else {
    out << "  " << c.problem << "\n";
  }
  return out.str();
}

std::string summaryLine(const std::vector<DiffCase>& cases) {
  std::array<int, static_cast<std::size_t>(Verdict::Count)> counts{};
  for (const DiffCase& c : cases) ++counts[static_cast<std::size_t>(c.verdict)];
  constexpr const char* kCountNames[][2] = {
      {"pass", "passes"}, {"warning", "warnings"}, {"failure", "failures"}, {"size mismatch", "size mismatches"}, {"file error", "file errors"}};
  static_assert(std::size(kCountNames) == static_cast<std::size_t>(Verdict::Count));
  std::ostringstream out;
  out << cases.size() << (cases.size() == 1 ? " case:" : " cases:");
  const char* separator = " ";
  for (std::size_t v = 0; v < counts.size(); ++v) {
    if (counts[v] == 0) continue;
    out << separator << counts[v] << " " << kCountNames[v][counts[v] == 1 ? 0 : 1];
    separator = ", ";
  }
  const Verdict worst = worstVerdict(cases);
  out << " -> " << verdictName(worst) << " (exit code " << static_cast<int>(worst) << ")";
  return out.str();
}

}  // namespace facet
