#!/usr/bin/env bash
# run.sh <pumpd> <path_change> <load_change> <source dir> <scene .prm> <work dir> <reference dir>
#        <metric> <limit mm> <load metric> "<first limit>;<mean limit>" [<file> "<numdiff options>"]...
# Runs pumpd on the scene (from the source directory: relative paths in a scene start there) with
# its output directory moved to <work dir>/out, then compares: each <file> of the reference with
# numdiff and its options, fields split at commas (the files are CSV); the crack path with
# path_change, printed as `pumpd-metric <metric> <mean distance in mm>` and failing above
# <limit mm> (empty: not compared); the loads of load_displacement.csv with load_change, printed
# as `pumpd-metric <load metric>_first_rel` and `<load metric>_mean_rel`, failing above the limits
# (relative; empty: not compared).
set -u
pumpd=$1 path_change=$2 load_change=$3 source=$4 prm=$5 work=$6 reference=$7 metric=$8 limit=$9
load_metric=${10} load_limits=${11}
shift 11
rm -rf "$work" && mkdir -p "$work"
sed "s#^\( *set Output directory *=\).*#\1 $work/out#" "$source/$prm" > "$work/scene.prm"
(cd "$source" && "$pumpd" "$work/scene.prm") > "$work/log" 2>&1
status=$?
tail -n 3 "$work/log"
[ $status -eq 0 ] || { echo "FAIL: pumpd exited with $status"; cat "$work/log"; exit 1; }
failed=0
while [ $# -ge 2 ]; do
  file=$1 options=$2
  shift 2
  # shellcheck disable=SC2086
  if numdiff -q -s ',\n' $options "$reference/$file" "$work/out/$file" > /dev/null; then
    echo "$file: as the reference (numdiff $options)"
  else
    echo "FAIL: $file differs from the reference beyond numdiff $options:"
    # shellcheck disable=SC2086
    numdiff -s ',\n' $options "$reference/$file" "$work/out/$file" | head -n 20
    failed=1
  fi
done
if [ -n "$limit" ]; then
  mean=$("$path_change" "$reference/crack_path.csv" "$work/out/crack_path.csv") || { echo "FAIL: path_change"; exit 1; }
  echo "pumpd-metric $metric $mean"
  awk -v m="$mean" -v l="$limit" 'BEGIN { exit !(m <= l) }' || { echo "FAIL: the crack path moved by $mean mm (mean), more than $limit mm"; failed=1; }
fi
if [ -n "$load_metric" ]; then
  read -r first_limit mean_limit <<< "${load_limits/;/ }"
  change=$("$load_change" "$reference/load_displacement.csv" "$work/out/load_displacement.csv") ||
    { echo "FAIL: load_change"; exit 1; }
  read -r first mean <<< "$change"
  echo "pumpd-metric ${load_metric}_first_rel $first"
  echo "pumpd-metric ${load_metric}_mean_rel $mean"
  awk -v f="$first" -v m="$mean" -v fl="$first_limit" -v ml="$mean_limit" 'BEGIN { exit !(f <= fl && m <= ml) }' ||
    { echo "FAIL: the loads moved by $first (first row), $mean (mean), relative; limits $first_limit, $mean_limit"; failed=1; }
fi
exit $failed
