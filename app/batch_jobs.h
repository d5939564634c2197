#pragma once
// The job file of `facet batch`: one JSON object a line, each a frame to
// render (and, with "expected", to compare). Read whole before anything runs,
// so that a bad line is known up front and fails alone, naming its line.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "compare/diff_thresholds.h"

namespace facet {

// The backends a job may name, as `facet render --backend` takes them.
inline constexpr std::string_view kBatchBackends[] = {"cpu", "gl", "ray", "reference"};

struct BatchJob {
  std::string scene;                     // a path (resolved against the job file's folder) or builtin:NAME; "" the default scene
  std::vector<std::string> assignments;  // "set": key=value, as --set, applied in order after "settings"
  std::string settingsJson;              // "settings": a settings object as JSON text; "" none
  std::string size;                      // "size": WxH; "" from the settings
  std::string backend = "cpu";
  std::string output;                    // resolved against the job file's folder
  std::string expected;                  // "" no comparison
  std::string folder;                    // the job file's folder: the settings' relative file names are taken from it
  DiffThresholds thresholds;             // facet diff's, when "expected" is given
};

// One counted line of the job file: a job, or why it is not one.
struct JobLine {
  int line = 0;                   // 1-based line number in the file
  std::optional<BatchJob> job;    // empty: `problem` says why
  std::string problem;            // "JOBS.jsonl:LINE: ..." when there is no job
  std::string output;             // the job's output when known (for reports), else ""
};

// `path` taken from `folder` when relative (a builtin: name or an absolute path as it is).
std::string resolvedPath(const std::string& path, const std::string& folder);

// A job from one line's text. Relative paths are taken from `folder`.
// Throws facet::Error with the key and the problem (no file or line).
BatchJob parseJob(std::string_view text, const std::string& folder);

// Every job line of `text` (the file `path` holds) in order: empty lines and
// lines starting with '#' are not jobs. A line that does not parse, or names
// an output an earlier job writes, becomes a JobLine with its problem.
std::vector<JobLine> parseJobFile(std::string_view text, const std::string& path);

// Reads `path` and parses it; throws facet::Error when the file cannot be read.
std::vector<JobLine> readJobFile(const std::string& path);

}  // namespace facet
