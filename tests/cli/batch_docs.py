"""The Kubernetes Job of docs/batch.md for facet batch: YAML that parses, an Indexed
Job whose completions match the shard count its command passes (a shard
left out would be a slice of jobs never run)."""
import re
import sys

import yaml

with open(sys.argv[1]) as f:
    job = yaml.safe_load(f)
spec = job["spec"]
assert job["apiVersion"] == "batch/v1" and job["kind"] == "Job", "not a batch/v1 Job"
assert spec["completionMode"] == "Indexed", "shards need an Indexed Job"
command = " ".join(spec["template"]["spec"]["containers"][0]["args"])
shards = re.search(r'--shard "\$\{JOB_COMPLETION_INDEX\}/(\d+)"', command)
assert shards, "the command passes no --shard ${JOB_COMPLETION_INDEX}/N"
assert int(shards.group(1)) == spec["completions"], "--shard N differs from completions"
assert spec["template"]["spec"]["restartPolicy"] in ("Never", "OnFailure")
print("ok")
