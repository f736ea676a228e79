#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Runs the paper's experiment on a Slurm cluster: a job array of SHARDS shards, then a merge job
# that starts when all of them have succeeded. Prints the two job ids.
#   apps/grasp_transfer/slurm/submit.sh SHARDS OUT [grasp_transfer options...]
# e.g. apps/grasp_transfer/slurm/submit.sh 16 $HOME/runs/seed2 --seed 2 --judge both
# The merged results are in OUT/merged (results.json, scenes/); each shard's log in
# OUT/logs/. PROGRAM defaults to build/release/apps/grasp_transfer under this checkout.
# Extra sbatch options (partition, account) go in SBATCH_OPTIONS, e.g. "--partition=cpu".
set -euo pipefail
if (($# < 2)); then
  echo "usage: $0 SHARDS OUT [grasp_transfer options...]" >&2
  exit 2
fi
shards=$1
out=$(realpath -m "$2")
shift 2
if ! [[ $shards =~ ^[1-9][0-9]*$ ]]; then
  echo "$0: SHARDS must be a positive integer, got '$shards'" >&2
  exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
program=$(realpath "${PROGRAM:-$here/../../../build/release/apps/grasp_transfer}")
if [[ ! -x $program ]]; then
  echo "$0: no grasp_transfer at $program (build it, or set PROGRAM)" >&2
  exit 2
fi
mkdir -p "$out/logs"
read -r -a sbatch_options <<< "${SBATCH_OPTIONS:-}"
export PROGRAM=$program OUT=$out SHARDS=$shards ARGS="$*"
array=$(sbatch --parsable "${sbatch_options[@]}" --array="1-$shards" --export=ALL \
  --output="$out/logs/shard-%a.log" "$here/shard.sbatch")
merge=$(sbatch --parsable "${sbatch_options[@]}" --dependency="afterok:${array%%;*}" \
  --export=ALL --output="$out/logs/merge.log" "$here/merge.sbatch")
echo "shards: job ${array%%;*} (array 1-$shards); merge: job ${merge%%;*} -> $out/merged"
