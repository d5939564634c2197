// The job file of facet batch: what a line may hold, and how a bad one fails alone.
#include <doctest/doctest.h>

#include "batch_jobs.h"
#include "common/error.h"

namespace facet {

TEST_CASE("a job line: every key, paths taken from the job file's folder") {
  const BatchJob job = parseJob(
      R"({"scene":"m/a.glb","set":["shading=flat"],"settings":{"ambient":0.2},"size":"64x48","backend":"gl",)"
      R"("output":"out/a.png","expected":"/abs/g.png","fail":0.01,"failpercent":2,"warn":0,"warnpercent":1,"hardfail":0.5,"hardwarn":0.4})",
      "jobs");
  CHECK(job.scene == "jobs/m/a.glb");
  CHECK(job.assignments == std::vector<std::string>{"shading=flat"});
  CHECK(job.settingsJson == R"({"ambient":0.2})");
  CHECK(job.size == "64x48");
  CHECK(job.backend == "gl");
  CHECK(job.output == "jobs/out/a.png");
  CHECK(job.expected == "/abs/g.png");
  CHECK(job.thresholds.failThreshold == 0.01);
  CHECK(job.thresholds.failPercent == 2);
  CHECK(job.thresholds.hardFail == 0.5);
  CHECK(job.thresholds.hardWarn == 0.4);
  CHECK(job.thresholds.warnPercent == 1);
}

TEST_CASE("a job line: builtin scenes stay as named, the backend defaults to cpu") {
  const BatchJob job = parseJob(R"({"scene":"builtin:cube","output":"a.png"})", "jobs");
  CHECK(job.scene == "builtin:cube");
  CHECK(job.backend == "cpu");
  CHECK(job.expected.empty());
}

TEST_CASE("a bad job line names the key and the problem") {
  const auto problem = [](const char* text) {
    try {
      parseJob(text, ".");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(problem("not json").find("not JSON") == 0);
  CHECK(problem("[1]").find("expected a JSON object") == 0);
  CHECK(problem(R"({"output":"a.png","bogus":1})").find("unknown key 'bogus'") == 0);
  CHECK(problem(R"({"scene":"a.glb"})").find("no \"output\"") == 0);
  CHECK(problem(R"({"output":"a.png","backend":"vulkan"})").find("key 'backend': 'vulkan'") == 0);
  CHECK(problem(R"({"output":"a.png","size":"0x5"})").find("key 'size': '0x5': each side") == 0);
  CHECK(problem(R"({"output":"a.png","set":"shading=flat"})").find("key 'set': expected an array") == 0);
  CHECK(problem(R"({"output":"a.png","settings":[]})").find("key 'settings': expected a settings object") == 0);
  CHECK(problem(R"({"output":"a.png","fail":0.1})").find("thresholds without \"expected\"") == 0);
  CHECK(problem(R"({"output":"a.png","expected":"g.png","fail":"x"})").find("key 'fail': expected a number") == 0);
  CHECK(problem(R"({"output":"a.png","expected":"g.png","failpercent":200})") != "no error");
  CHECK(problem(R"({"output":"a.png","output":"b.png"})") != "no error");  // a key twice
}

TEST_CASE("a job file: comments and empty lines skipped, a bad line fails alone with its number") {
  const std::vector<JobLine> lines = parseJobFile(
      "# jobs\n"
      "{\"output\":\"a.png\"}\n"
      "\n"
      "  \r\n"
      "{nope\n"
      "{\"output\":\"b.png\",\"colour\":1}\r\n"
      "{\"output\":\"c.png\"}\n"
      "{\"output\":\"./a.png\"}",
      "dir/jobs.jsonl");
  REQUIRE(lines.size() == 5);
  CHECK(lines[0].line == 2);
  CHECK(lines[0].job);
  CHECK(lines[1].line == 5);
  CHECK_FALSE(lines[1].job);
  CHECK(lines[1].problem.find("dir/jobs.jsonl:5: not JSON") == 0);
  CHECK(lines[2].line == 6);
  CHECK(lines[2].problem.find("dir/jobs.jsonl:6: unknown key 'colour'") == 0);
  CHECK(lines[3].job);
  CHECK(lines[3].job->output == "dir/c.png");
  CHECK(lines[4].line == 8);
  CHECK(lines[4].problem.find("dir/jobs.jsonl:8: output dir/a.png is written by line 2 already") == 0);
}

TEST_CASE("a job file: a comparison with a file the batch writes is refused, whichever line writes it") {
  const std::vector<JobLine> lines = parseJobFile(
      "{\"output\":\"a.png\",\"expected\":\"./b.png\"}\n"
      "{\"output\":\"b.png\"}\n"
      "{\"output\":\"c.png\",\"expected\":\"c.png\"}\n"
      "{\"output\":\"d.png\",\"expected\":\"a.png\"}\n"
      "{\"output\":\"e.png\",\"expected\":\"golden/e.png\"}\n",
      "dir/jobs.jsonl");
  REQUIRE(lines.size() == 5);
  CHECK_FALSE(lines[0].job);
  CHECK(lines[0].problem == "dir/jobs.jsonl:1: expected dir/b.png is written by line 2");
  CHECK(lines[0].output == "dir/a.png");
  CHECK(lines[1].job);
  CHECK_FALSE(lines[2].job);
  CHECK(lines[2].problem == "dir/jobs.jsonl:3: expected dir/c.png is this job's own output");
  CHECK(lines[3].problem == "dir/jobs.jsonl:4: expected dir/a.png is written by line 1");
  REQUIRE(lines[4].job);
  CHECK(lines[4].job->expected == "dir/golden/e.png");
}

}  // namespace facet
