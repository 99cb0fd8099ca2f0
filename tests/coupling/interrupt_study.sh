#!/usr/bin/env bash
# interrupt_study.sh <pumpd> <scene.prm> <its output directory>: runs `pumpd --study` on the scene
# (its output directory removed first, so that it runs its runs), sends it SIGTERM while a run's
# pumpd runs, and passes if the study ends as the signal would (exit 143) with one line on stderr
# and no run's pumpd outlives it.
set -u
pumpd=$1 scene=$2 output=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$output"
err=$(mktemp)
trap 'rm -f "$err"' EXIT
"$pumpd" --study "$scene" > /dev/null 2> "$err" &
study=$!
child=
for _ in $(seq 1200); do
  child=$(ps -o pid=,comm= --ppid "$study" | awk '$2 == "pumpd" { print $1; exit }')
  [ -n "$child" ] && break
  kill -0 "$study" 2> /dev/null || fail "the study ended before a run started: $(cat "$err")"
  sleep 0.1
done
[ -n "$child" ] || fail "no run's pumpd started within 120 s"
echo "study $study, its run $child: $(tr '\0' ' ' < /proc/"$child"/cmdline)"
sleep 0.5
kill -TERM "$study"
wait "$study"
status=$?
echo "exit $status: $(cat "$err")"
[ "$status" -eq 143 ] || fail "exit $status, expected 143 (128 + SIGTERM)"
[ "$(wc -l < "$err")" -eq 1 ] || fail "expected one line on stderr"
grep -Eq "^pumpd: stopped in .*: SIGTERM while waiting for .*pumpd" "$err" || fail "stderr does not say that SIGTERM stopped the study"
! kill -0 "$child" 2> /dev/null || fail "the run's pumpd ($child) outlived the study"
! pgrep -f -- "$output/" > /dev/null || fail "a process of the study's runs still runs: $(pgrep -af -- "$output/")"
echo "ok"
