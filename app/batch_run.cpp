#include "batch_run.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "command_line.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "common/stopwatch.h"
#include "compare/compare_files.h"
#include "compare/diff_format.h"
#include "compare/diff_text.h"
#include "frame_setup.h"
#include "image/png.h"
#include "image/png_text.h"
#include "inputs_hash.h"
#include "pipeline/frame_spine.h"
#include "render/stage.h"
#include "scene/load_scene.h"
#include "settings/settings_files.h"
#include "settings/settings_json.h"
#if FACET_HAVE_GL
#include "gl/gl_renderer.h"
#include "vocabulary/limits.h"
#endif

namespace facet {
namespace {

namespace fs = std::filesystem;


struct LoadedScene {
  Scene scene;
  std::string hashed;  // the digest of the files it was read from, or the builtin name
};

// Each scene path loaded once, the first job to ask doing the work and the
// others waiting for it; a scene that fails to load fails every job naming it.
class SceneCache {
 public:
  std::shared_ptr<const LoadedScene> get(const std::string& path) {
    std::shared_future<std::shared_ptr<const LoadedScene>> future;
    std::optional<std::promise<std::shared_ptr<const LoadedScene>>> mine;
    {
      const std::lock_guard lock(mutex_);
      auto found = scenes_.find(path);
      if (found == scenes_.end()) {
        mine.emplace();
        found = scenes_.emplace(path, mine->get_future().share()).first;
      }
      future = found->second;
    }
    if (mine) {
      try {
        auto loaded = std::make_shared<LoadedScene>();
        loaded->scene = loadScene(path);
        loaded->hashed = loaded->scene.files.empty() ? "builtin:" + path : filesDigest(loaded->scene.files, kMaxHashedFileBytes);
        mine->set_value(std::move(loaded));
      } catch (...) {
        mine->set_exception(std::current_exception());
      }
    }
    return future.get();
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::shared_future<std::shared_ptr<const LoadedScene>>> scenes_;
};

// The digest of the files a job's settings name (maps, volume, sprites),
// read once per list for the whole batch: a thousand jobs over one
// environment map read it once, not a thousand times.
class NamedFilesDigests {
 public:
  std::string of(const std::vector<std::string>& files) {
    if (files.empty()) return filesDigest(files, kMaxHashedFileBytes);
    std::string key;
    for (const std::string& file : files) key += file + '\n';
    {
      const std::lock_guard lock(mutex_);
      if (const auto found = digests_.find(key); found != digests_.end()) return found->second;
    }
    std::string digest = filesDigest(files, kMaxHashedFileBytes);  // outside the lock: other workers go on
    const std::lock_guard lock(mutex_);
    return digests_.emplace(key, std::move(digest)).first->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::string> digests_;
};

// What one worker thread keeps between jobs.
struct Worker {
  std::map<std::string, std::unique_ptr<Renderer>> renderers;  // by backend, made on first use
  // The spine of the last job's scene: the files its settings name are read
  // once for the jobs after it (pipeline/frame_spine.h).
  std::optional<FrameSpine> spine;
  // The last frame prepared, reused when the next job has the same scene
  // and settings (a GL renderer then keeps its buffers too).
  std::string preparedKey;
  std::optional<PreparedFrame> prepared;

  Renderer& renderer(const std::string& backend, int threads) {
    std::unique_ptr<Renderer>& r = renderers[backend];
    if (!r) r = makeBackend(backend, "osmesa", threads);
    return *r;
  }
};

RenderSettings baseSettings(const BatchJob& job) {
  if (job.settingsJson.empty()) return RenderSettings{};
  try {
    return settingsFromJson(nlohmann::json::parse(job.settingsJson));
  } catch (const Error& e) {
    throw Error(std::string("key 'settings': ") + e.what());
  }
}

// The one line a report gives a comparison: what failed and by how much.
std::string figuresLine(const DiffResult& r) {
  return formatPixels(r.failingPixels) + " (" + formatNumber(r.failingPercent) + "%) over --fail, " + formatPixels(r.warningPixels) + " (" +
         formatNumber(r.warningPercent) + "%) over --warn, largest difference " + std::to_string(r.maxDifference) + "/255, RMSE " +
         formatNumber(r.rmse) + ", PSNR " + formatNumber(r.psnr) + " dB";
}

// The output holds the hash of these inputs, and decodes whole, at the
// size asked, by the reader facet diff uses: an image damaged after it was
// written (a bad CRC, a cut IDAT) is rendered again, not kept.
bool upToDate(const std::string& output, const std::string& hash, int width, int height) {
  std::error_code ec;
  if (!fs::is_regular_file(output, ec)) return false;
  try {
    const std::string bytes = readFile(output, kMaxPngFileBytes);
    if (textChunk(bytes, kInputsKeyword) != hash) return false;
    const Image image = decodePng(bytes, output);
    return image.width() == width && image.height() == height;
  } catch (const Error&) {
    return false;  // unreadable: rendered again, and the write says what is wrong
  }
}

// One job, start to end; throws facet::Error for what makes it fail.
void runJob(const BatchJob& job, const BatchOptions& options, SceneCache& scenes, NamedFilesDigests& digests, Worker& worker, JobOutcome& outcome) {
  // Before any work: a frame nobody can write is not drawn.
  checkOutputFile(job.output, {job.scene, job.expected, options.jobFile}, MissingFolders::Created);
  const std::shared_ptr<const LoadedScene> loaded = scenes.get(job.scene);
  RenderSettings asked = settingsFor(baseSettings(job), job.assignments, job.size, loaded->scene);
  forEachNamedFile(asked, [&](std::string& file) { file = resolvedPath(file, job.folder); });  // as the job's other paths
  // Nor a file the scene was read from (its buffers, images) or one the settings name.
  std::vector<std::string> read = loaded->scene.files;
  for (const std::string& file : namedFiles(asked)) read.push_back(file);
  if (const std::string same = sameFileAsInput(job.output, read); !same.empty()) throw Error(same);
  const std::string settingsText = settingsToJson(asked).dump();
  // The scene's files, and the maps, volume and sprites the settings name.
  const std::string files = loaded->hashed + digests.of(namedFiles(asked));
  const std::string hash = inputsHash(files, settingsText, asked.width, asked.height, job.backend, options.version);
  if (options.resume && upToDate(job.output, hash, asked.width, asked.height)) {
    outcome.status = JobStatus::Skipped;
  } else {
    const std::string key = job.scene + '\n' + settingsText;
    if (!worker.prepared || worker.preparedKey != key) {
      worker.prepared.reset();
      const std::shared_ptr<const Scene> scene(loaded, &loaded->scene);
      if (!worker.spine) worker.spine.emplace(scene, options.cpuThreads);
      else if (worker.spine->loaded() != scene) worker.spine->setLoaded(scene);
      worker.prepared = worker.spine->frame(asked);
      worker.preparedKey = key;
    }
#if FACET_HAVE_GL
    if (job.backend == "gl") refuseCpuOnlyFrame(worker.prepared->inputs);
#endif
    Renderer& renderer = worker.renderer(job.backend, options.cpuThreads);
    const RenderResult result = renderStage(renderer, *worker.prepared->scene, worker.prepared->inputs, Stage{});
    const std::string folder = fs::path(job.output).parent_path().string();
    std::error_code ec;
    if (!folder.empty()) fs::create_directories(folder, ec);  // a failure shows when writing
    writeFileAtomically(job.output, withTextChunk(encodePng(result.image, job.output), kInputsKeyword, hash));
  }
  if (!job.expected.empty()) {
    const ComparedFiles compared = compareFiles(fs::path(job.output).filename().string(), job.expected, job.output, job.thresholds);
    outcome.compared = true;
    outcome.verdict = compared.diffCase.verdict;
    outcome.message = compared.diffCase.result ? figuresLine(*compared.diffCase.result) : compared.diffCase.problem;
    outcome.details = caseText(compared.diffCase, job.thresholds);
  }
}

}  // namespace

std::vector<JobOutcome> runBatch(const std::vector<JobLine>& jobs, const BatchOptions& options,
                                 const std::function<void(const JobOutcome&)>& finished) {
  std::vector<JobOutcome> outcomes(jobs.size());
  std::mutex reporting;
  const auto report = [&](const JobOutcome& outcome) {
    const std::lock_guard lock(reporting);
    finished(outcome);
  };
  const auto fail = [&](JobOutcome& outcome, const std::string& message) {
    outcome.status = JobStatus::Failed;
    outcome.verdict = Verdict::FileError;
    outcome.compared = false;
    outcome.details.clear();
    outcome.message = options.jobFile + ":" + std::to_string(outcome.line) + ": " + message;
  };
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    outcomes[k].line = jobs[k].line;
    outcomes[k].output = jobs[k].output;
    if (!jobs[k].job) {
      outcomes[k].status = JobStatus::Failed;
      outcomes[k].verdict = Verdict::FileError;
      outcomes[k].message = jobs[k].problem;
      report(outcomes[k]);
    }
  }
  SceneCache scenes;
  NamedFilesDigests digests;
  std::atomic<std::size_t> next{0};
  const auto work = [&]() {
    Worker worker;
    for (std::size_t k; (k = next.fetch_add(1)) < jobs.size();) {
      if (!jobs[k].job) continue;
      JobOutcome& outcome = outcomes[k];
      const auto start = std::chrono::steady_clock::now();
      try {
        runJob(*jobs[k].job, options, scenes, digests, worker, outcome);
      } catch (const Error& e) {
        fail(outcome, e.what());
      } catch (const fs::filesystem_error& e) {
        fail(outcome, e.what());
      } catch (const std::bad_alloc&) {
        fail(outcome, "out of memory");
        worker = Worker{};  // what it kept may be the cause
      }
      outcome.milliseconds = millisecondsSince(start);
      report(outcome);
    }
  };
  const int threads = std::max(1, std::min<int>(options.workers, static_cast<int>(jobs.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  return outcomes;
}

}  // namespace facet
