#!/bin/bash
# facet batch on Slurm: a job array of 4 tasks, each running one shard of
# the job list. The array starts at 0, since shards count from 0
# (SLURM_ARRAY_TASK_ID is the shard's I). Submit with `sbatch
# docs/batch-slurm.sh`, then, when every task is done:
#   facet batch --merge reports/all.xml reports/shard-*.xml
#SBATCH --job-name=facet-batch
#SBATCH --array=0-3
#SBATCH --cpus-per-task=4
#SBATCH --mem=4G
#SBATCH --output=logs/facet-batch-%a.log
set -euo pipefail
shards=4
mkdir -p reports
facet batch jobs.jsonl --resume --jobs "${SLURM_CPUS_PER_TASK:-1}" \
  --shard "${SLURM_ARRAY_TASK_ID}/${shards}" \
  --junit "reports/shard-${SLURM_ARRAY_TASK_ID}.xml"
