#!/usr/bin/env bash
# interrupt_meshing.sh <pumpd> <scene.prm> <scratch directory> <INT|TERM> [heartbeat]: runs pumpd on
# a scene whose .geo a gmsh that never finishes meshes (bad_prm/slow-gmsh.sh), sends it the signal
# while gmsh runs (with `heartbeat`, after the first progress line of the meshing, which it checks),
# and passes if pumpd ends as the signal would (exit 128 + signal) with one line on stderr, gmsh
# and everything it started are gone, and so is pumpd's temporary directory.
set -u
pumpd=$1 scene=$2 scratch=$3 signal=$4 heartbeat=${5:-}
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$scratch" && mkdir -p "$scratch" || fail "cannot make $scratch"
export TMPDIR=$scratch PUMPD_GMSH=$(dirname "$0")/bad_prm/slow-gmsh.sh
unset PUMPD_MESH_CACHE
set -m # a background job of a script without job control would ignore SIGINT
"$pumpd" "$scene" > "$scratch/out.txt" 2> "$scratch/err.txt" &
pid=$!
set +m
waited_for() { # <seconds> <command...>: until the command succeeds
  local limit=$1; shift
  for _ in $(seq $((limit * 10))); do "$@" && return 0; sleep 0.1; done
  return 1
}
waited_for 30 test -s "$scratch/gmsh.pid" || fail "gmsh did not start within 30 s"
gmsh=$(cat "$scratch/gmsh.pid")
ls -d "$scratch"/pumpd-mesh-* > /dev/null 2>&1 || fail "no temporary directory pumpd-mesh-* while gmsh runs"
if [ -n "$heartbeat" ]; then
  waited_for 20 grep -q "^meshing " "$scratch/out.txt" || fail "no progress line within 20 s of meshing"
  line=$(grep "^meshing " "$scratch/out.txt" | head -1)
  echo "progress: $line"
  echo "$line" | grep -Eq "^meshing .*plate\.geo: 1[0-9] s, gmsh log: Info : Meshing 2D\.\.\.$" ||
    fail "the progress line does not read 'meshing <file>: <seconds> s, gmsh log: <its last line>'"
fi
kill -"$signal" "$pid"
wait "$pid"
status=$?
expected=$((128 + $(kill -l "$signal")))
echo "exit $status: $(cat "$scratch/err.txt")"
[ "$status" -eq "$expected" ] || fail "exit $status, expected $expected (128 + SIG$signal)"
[ "$(wc -l < "$scratch/err.txt")" -eq 1 ] || fail "expected one line on stderr"
grep -Eq "^pumpd: stopped in .*: SIG$signal while waiting for .*slow-gmsh\.sh" "$scratch/err.txt" ||
  fail "stderr does not say that SIG$signal stopped the meshing"
! kill -0 "$gmsh" 2> /dev/null || fail "gmsh ($gmsh) still runs"
! pgrep -g "$gmsh" > /dev/null || fail "a process of gmsh's process group still runs"
! ls -d "$scratch"/pumpd-mesh-* > /dev/null 2>&1 || fail "the temporary directory is left: $(ls -d "$scratch"/pumpd-mesh-*)"
echo "ok"
