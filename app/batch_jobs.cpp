#include "batch_jobs.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include <nlohmann/json.hpp>

#include "command_line.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/json_text.h"
#include "common/quote.h"
#include "vocabulary/limits.h"

namespace facet {
namespace {

using nlohmann::json;


std::string keyName(std::string_view key) { return "key " + quoteInput(key); }

std::string stringOf(const json& value, std::string_view key) {
  if (!value.is_string()) throw Error(keyName(key) + ": expected a string, got " + describeJson(value));
  const std::string text = value.get<std::string>();
  if (text.empty()) throw Error(keyName(key) + ": an empty string");
  return text;
}

double thresholdOf(const json& value, std::string_view key) {
  if (!value.is_number()) throw Error(keyName(key) + ": expected a number, got " + describeJson(value));
  return value.get<double>();
}

}  // namespace

std::string resolvedPath(const std::string& path, const std::string& folder) {
  if (path.rfind("builtin:", 0) == 0 || std::filesystem::path(path).is_absolute() || folder.empty() || folder == ".") return path;
  return (std::filesystem::path(folder) / path).lexically_normal().string();
}

BatchJob parseJob(std::string_view text, const std::string& folder) {
  json object;
  try {
    object = parseStrictJson(text, kMaxJobDepth);
  } catch (const JsonSyntaxError& e) {
    throw Error(std::string("not JSON: ") + e.what());
  }
  if (!object.is_object()) throw Error("expected a JSON object, got " + describeJson(object));
  BatchJob job;
  job.folder = folder;
  bool haveOutput = false, haveExpected = false, haveThreshold = false;
  for (const auto& [key, value] : object.items()) {
    if (key == "scene") {
      job.scene = resolvedPath(stringOf(value, key), folder);
    } else if (key == "set") {
      if (!value.is_array()) throw Error(keyName(key) + ": expected an array of \"key=value\" strings, got " + describeJson(value));
      for (const json& item : value) job.assignments.push_back(stringOf(item, key));
    } else if (key == "settings") {
      if (!value.is_object()) throw Error(keyName(key) + ": expected a settings object, got " + describeJson(value));
      job.settingsJson = value.dump();
    } else if (key == "size") {
      job.size = stringOf(value, key);
      int width = 0, height = 0;
      try {
        parseSize(job.size, width, height);
      } catch (const Error& e) {
        throw Error(keyName(key) + ": " + std::string(e.what()).substr(std::string("--size ").size()));
      }
    } else if (key == "backend") {
      job.backend = stringOf(value, key);
      if (std::find(std::begin(kBatchBackends), std::end(kBatchBackends), job.backend) == std::end(kBatchBackends))
        throw Error(keyName(key) + ": " + quoteInput(job.backend) + ": expected cpu, gl, ray or reference");
    } else if (key == "output") {
      job.output = resolvedPath(stringOf(value, key), folder);
      haveOutput = true;
    } else if (key == "expected") {
      job.expected = resolvedPath(stringOf(value, key), folder);
      haveExpected = true;
    } else if (key == "fail") {
      job.thresholds.failThreshold = thresholdOf(value, key), haveThreshold = true;
    } else if (key == "failpercent") {
      job.thresholds.failPercent = thresholdOf(value, key), haveThreshold = true;
    } else if (key == "hardfail") {
      job.thresholds.hardFail = thresholdOf(value, key), haveThreshold = true;
    } else if (key == "warn") {
      job.thresholds.warnThreshold = thresholdOf(value, key), haveThreshold = true;
    } else if (key == "warnpercent") {
      job.thresholds.warnPercent = thresholdOf(value, key), haveThreshold = true;
    } else if (key == "hardwarn") {
      job.thresholds.hardWarn = thresholdOf(value, key), haveThreshold = true;
    } else {
      throw Error("unknown " + keyName(key) +
                  " (keys: scene, set, settings, size, backend, output, expected, fail, failpercent, warn, warnpercent, hardfail, hardwarn)");
    }
  }
  if (!haveOutput) throw Error("no \"output\": every job names the PNG it writes");
  if (haveThreshold && !haveExpected) throw Error("thresholds without \"expected\": they apply to a comparison");
  checkThresholds(job.thresholds);
  return job;
}

std::vector<JobLine> parseJobFile(std::string_view text, const std::string& path) {
  const std::string folder = folderOf(path);
  std::vector<JobLine> lines;
  std::map<std::string, int> outputLines;  // output -> the line that writes it
  int number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string_view::npos || line[first] == '#') continue;
    JobLine entry;
    entry.line = number;
    try {
      BatchJob job = parseJob(line, folder);
      entry.output = job.output;
      // Two jobs writing one file would race; the second is the mistake. One
      // file whatever the spelling: out/a.png, $PWD/out/a.png, link/a.png.
      const auto [at, fresh] = outputLines.emplace(fileIdentityKey(job.output), number);
      if (!fresh) throw Error("output " + shownPath(job.output) + " is written by line " + std::to_string(at->second) + " already");
      entry.job = std::move(job);
    } catch (const Error& e) {
      entry.problem = path + ":" + std::to_string(number) + ": " + e.what();
    }
    lines.push_back(std::move(entry));
  }
  // A comparison with a file the batch writes would read it before, while or after it is
  // written, as the jobs' order on the threads falls; this job's own output, after.
  for (JobLine& entry : lines) {
    if (!entry.job || entry.job->expected.empty()) continue;
    const auto writer = outputLines.find(fileIdentityKey(entry.job->expected));
    if (writer == outputLines.end()) continue;
    entry.problem = path + ":" + std::to_string(entry.line) + ": expected " + shownPath(entry.job->expected) +
                    (writer->second == entry.line ? " is this job's own output" : " is written by line " + std::to_string(writer->second));
    entry.job.reset();
  }
  return lines;
}

std::vector<JobLine> readJobFile(const std::string& path) { return parseJobFile(readFile(path, kMaxJobFileBytes), path); }

}  // namespace facet
