#!/usr/bin/env bash
# Two builds of gvm on every shared part, alternating part by part so that the drift of a
# shared machine falls on both alike: `gvm analyze PART -q --threads T`, wall seconds.
#
#   benchmarks/compare_builds.sh GVM_BEFORE GVM_AFTER [THREADS] [PARTS_DIR]
set -euo pipefail
before=$1 after=$2 threads=${3:-2} parts=${4:-../shared/data/parts}
[[ -x $before && -x $after && -d $parts ]] || { echo "usage: $0 GVM_BEFORE GVM_AFTER [THREADS] [PARTS_DIR]" >&2; exit 2; }
seconds() { local s e; s=$(date +%s.%N); "$@" > /dev/null; e=$(date +%s.%N); echo "$e - $s" | bc; }
total_before=0 total_after=0
printf "| part | before s | after s |\n|---|---:|---:|\n"
for part in "$parts"/*.{stl,STL,off,obj,ply}; do
  [[ -e $part ]] || continue
  b=$(seconds "$before" analyze "$part" -q --threads "$threads")
  a=$(seconds "$after" analyze "$part" -q --threads "$threads")
  total_before=$(echo "$total_before + $b" | bc) total_after=$(echo "$total_after + $a" | bc)
  printf "| %s | %.2f | %.2f |\n" "$(basename "$part")" "$b" "$a"
done
printf "| all | %.1f | %.1f |\n" "$total_before" "$total_after"
