#!/usr/bin/env bash
# output_lock.sh <pumpd> <scene> [--study]: two pumpd (or two pumpd --study) started at once in
# one output directory: the second is refused with one line naming the Output directory and the
# first's pid, before it writes anything; the first ends as if alone (each exchange's row once;
# a study's every run once and ok: its runs, child processes writing into sub-directories of the
# study's directory, are not refused by the study's lock).
set -u
pumpd=$1 base=$2 mode=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d /tmp/pumpd-output-lock-XXXXXX)
trap 'kill $pid 2>/dev/null; wait 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

dir=$tmp/out
section=Scene
[ "$mode" = --study ] && section=Study
# A single run goes on until its crack reaches the back edge: long enough for the second to reach
# its first write.
limit=
[ "$mode" = --study ] || limit=$'subsection Global-local\n  set Maximum exchanges = 30\nend'
cat > "$tmp/scene.prm" <<END
include $base
subsection $section
  set Output directory = $dir
end
$limit
END
"$pumpd" $mode "$tmp/scene.prm" > "$tmp/first.log" 2>&1 &
pid=$!
while [ ! -s "$dir/.pumpd.lock" ] && kill -0 $pid 2>/dev/null; do sleep 0.01; done
kill -0 $pid 2>/dev/null || { tail -3 "$tmp/first.log"; fail "the first run ended before it wrote"; }
"$here/expect_error.sh" "$pumpd" $mode "$tmp/scene.prm" -- \
  "Output directory = $dir: another pumpd \(pid $pid\) writes there" || exit 1
kill -0 $pid 2>/dev/null || fail "the first run had ended while the second was refused: lengthen the scene"
wait $pid
status=$?
pid=
[ $status -eq 0 ] || { tail -3 "$tmp/first.log"; fail "the first run exited $status"; }
if [ "$mode" = --study ]; then
  keys=$(cut -d, -f2 "$dir/runs.csv" | tail -n +2)
  [ -n "$keys" ] || fail "runs.csv has no runs"
  [ "$(echo "$keys" | sort | uniq -d)" = "" ] || fail "a study key twice in runs.csv"
  not_ok=$(awk -F, 'NR > 1 && $4 != "ok"' "$dir/runs.csv")
  [ -z "$not_ok" ] || fail "a run of the study not ok: $not_ok"
  echo "the first study ran $(echo "$keys" | wc -l) runs, each once and ok"
else
  exchanges=$(cut -d, -f1 "$dir/load_steps.csv" | tail -n +2)
  [ "$(echo "$exchanges" | sort | uniq -d)" = "" ] || fail "an exchange twice in load_steps.csv"
  echo "the first run wrote exchanges $(echo $exchanges)"
fi
