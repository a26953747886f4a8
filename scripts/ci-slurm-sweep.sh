#!/usr/bin/env bash
# CI: a sweep of 64 cases run on this machine and as a job array on a real single-node Slurm
# (scripts/slurm-local.sh), merged and compared byte for byte. Needs root and the packages
# slurm-wlm and munge (scripts/setup.sh --with-slurm installs them).
#   ci-slurm-sweep.sh BUILD_DIR
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:?usage: ci-slurm-sweep.sh BUILD_DIR}" && pwd)
vbim="$build/cli/vbim"
plan=tests/sweep/plans/array64.toml
work=$(mktemp -d "${TMPDIR:-/tmp}/vbim-slurm-sweep.XXXXXX")
cleanup() {
  bash scripts/slurm-local.sh stop "$work/slurm" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

"$vbim" profile --plan "$plan" --jobs 2 --out "$work/local" >/dev/null
bash scripts/slurm-local.sh start "$work/slurm"
export SLURM_CONF="$work/slurm/etc/slurm.conf"
"$vbim" profile --plan "$plan" --emit-slurm "$work/array" --shards 8
job=$(sbatch --parsable "$work/array/sweep.sbatch")
echo "ci-slurm-sweep: job array $job submitted"
# Poll the queue (sbatch --wait polls every 10 s); give up after 4 minutes.
for _ in $(seq 1200); do
  [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && break
  sleep 0.2
done
if [ -n "$(squeue -h -j "$job" 2>/dev/null)" ]; then
  echo "ci-slurm-sweep: job array $job still queued or running after 4 minutes" >&2
  squeue -j "$job" >&2 || true
  exit 1
fi
# Each task's exit code (no accounting database here: scontrol keeps finished jobs MinJobAge s).
if scontrol show job "$job" | grep -o 'ExitCode=[0-9:]*' | grep -qv 'ExitCode=0:0'; then
  echo "ci-slurm-sweep: a task failed:" >&2
  scontrol show job "$job" | grep -E 'JobId|ExitCode' >&2
  cat "$work"/array/logs/*.out >&2 || true
  exit 1
fi
"$vbim" profile --plan "$plan" --merge "$work/array/shards" --out "$work/merged" >/dev/null
diff -r "$work/local" "$work/merged"
echo "ci-slurm-sweep: $(($(wc -l <"$work/merged/cases.csv") - 1)) cases as an 8-task job array on Slurm: the same bytes as the local run"
