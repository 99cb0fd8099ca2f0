#!/usr/bin/env bash
# resume_faults.sh <pumpd> <base scene> <mode>: a global-local run interrupted by a fault, then
# resumed (Global-local/Resume = true), writes the same files as the run left alone: the tables
# (but their timings), the ParaView series, the VTU files, bit for bit (the cycle is
# deterministic). Modes:
#   kill        SIGKILL just after a row of load_steps.csv is written, before its checkpoint;
#   full-disk   the run's file system (a 40 MB tmpfs) filled while it runs: one line naming the
#               file and the cause, no truncated file left, and the resumed run on a freed disk;
#               without tmpfs (not root) a table on /dev/full: the line only;
#   flipped-bit one bit of the checkpoint flipped: the resume is refused, naming Resume and the file;
#   small-disk  the PD edge crack at 10000 load steps into the 40 MB tmpfs: refused before it runs
#               (skipped, exit 77, without tmpfs).
set -u
pumpd=$1 base=$2 mode=$3
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d /tmp/pumpd-resume-faults-XXXXXX)
mnt=$tmp/disk
cleanup() { mountpoint -q "$mnt" 2>/dev/null && umount "$mnt"; rm -rf "$tmp"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# scene <name> <output dir> <resume> [maximum exchanges]: a scene file on the base scene.
scene() {
  cat > "$tmp/$1.prm" <<END
include $base
subsection Scene
  set Output directory = $2
end
subsection Global-local
  set Resume = $3
  set Maximum exchanges = ${4:-5}
end
END
  echo "$tmp/$1.prm"
}

# rows <dir>: the lines of its load_steps.csv (0 before it exists).
rows() { if [ -f "$1/load_steps.csv" ]; then wc -l < "$1/load_steps.csv"; else echo 0; fi; }

# same_outputs <dir> <dir>: the files of the two runs agree (load_steps.csv but its seconds_* columns).
same_outputs() {
  for f in load_displacement.csv crack_path.csv boxes.csv global.pvd pd.pvd; do
    cmp -s "$1/$f" "$2/$f" || { diff "$1/$f" "$2/$f" | head -5; fail "$f differs from the uninterrupted run's"; }
  done
  cmp -s <(cut -d, -f1-18,23- "$1/load_steps.csv") <(cut -d, -f1-18,23- "$2/load_steps.csv") ||
    { diff <(cut -d, -f1,13 "$1/load_steps.csv") <(cut -d, -f1,13 "$2/load_steps.csv"); fail "load_steps.csv differs from the uninterrupted run's"; }
  [ "$(cd "$1" && ls ./*.vtu)" = "$(cd "$2" && ls ./*.vtu)" ] || fail "the VTU files differ from the uninterrupted run's"
  for f in "$1"/*.vtu; do cmp -s "$f" "$2/$(basename "$f")" || fail "$(basename "$f") differs from the uninterrupted run's"; done
  echo "the resumed run's files are the uninterrupted run's ($(($(rows "$2") - 1)) rows of load_steps.csv)"
}

# resume <name> <dir>: resumes the run in dir; prints the exchanges its checkpoint held.
resume() {
  "$pumpd" "$(scene "$1" "$2" true)" > "$tmp/$1.log" 2> "$tmp/$1.err" || { cat "$tmp/$1.err"; fail "the resumed run failed"; }
  [ -s "$tmp/$1.err" ] && { cat "$tmp/$1.err"; fail "the resumed run wrote to stderr"; }
  sed -n 's/^resuming after exchange \([0-9]*\):.*/\1/p' "$tmp/$1.log"
}

whole() {
  "$pumpd" "$(scene whole "$tmp/whole" false)" > "$tmp/whole.log" 2>&1 || { tail -3 "$tmp/whole.log"; fail "the uninterrupted run failed"; }
}

case $mode in
kill)
  whole
  # The window between a row and its checkpoint is the rest of the exchange's writing (a VTU of
  # the global solution, MBs); polled at a millisecond or so, a kill lands in it, else the next
  # exchange is tried. From the second exchange on: a run killed before its first checkpoint has
  # nothing to resume.
  for k in 2 3 4; do
    dir=$tmp/killed$k
    "$pumpd" "$(scene killed$k "$dir" false)" > "$tmp/killed$k.log" 2>&1 &
    pid=$!
    while [ "$(rows "$dir")" -lt $((k + 1)) ] && kill -0 $pid 2>/dev/null; do :; done
    kill -KILL $pid 2>/dev/null
    wait $pid 2>/dev/null
    written=$(($(rows "$dir") - 1))
    held=$(resume resumed$k "$dir") || exit 1
    echo "killed after $written rows of load_steps.csv; the checkpoint held $held exchanges"
    if [ "$held" -lt "$written" ]; then
      same_outputs "$tmp/whole" "$dir"
      exit 0
    fi
  done
  fail "no kill landed between a row of load_steps.csv and its checkpoint"
  ;;
full-disk)
  mkdir -p "$mnt"
  if mount -t tmpfs -o size=40m tmpfs "$mnt" 2>/dev/null; then
    whole
    dir=$mnt/run
    "$pumpd" "$(scene full "$dir" false)" > "$tmp/full.log" 2> "$tmp/full.err" &
    pid=$!
    while [ "$(rows "$dir")" -lt 3 ] && kill -0 $pid 2>/dev/null; do :; done
    dd if=/dev/zero of="$mnt/filler" bs=64k 2>/dev/null
    wait $pid
    status=$?
    echo "exit $status: $(cat "$tmp/full.err")"
    [ $status -ne 0 ] || fail "the run on a full disk exited 0"
    [ "$(wc -l < "$tmp/full.err")" -eq 1 ] || fail "expected one line on stderr"
    grep -Eq "cannot write $dir/[^ ]+: No space left on device" "$tmp/full.err" || fail "the line does not name the file and the cause"
    ls "$dir" | grep -q '\.partial$' && fail "a partial file was left behind: $(ls "$dir" | grep '\.partial$')"
    for f in "$dir"/*.vtu; do [ "$(tail -c 11 "$f")" = "</VTKFile>" ] || fail "$(basename "$f") is truncated"; done
    rm "$mnt/filler"
    resume resumed "$dir" > /dev/null || exit 1
    same_outputs "$tmp/whole" "$dir"
  else
    echo "no tmpfs (not root): load_steps.csv on /dev/full"
    mkdir -p "$tmp/full"
    ln -s /dev/full "$tmp/full/load_steps.csv"
    "$here/expect_error.sh" "$pumpd" "$(scene full "$tmp/full" false)" -- \
      "cannot write $tmp/full/load_steps.csv: No space left on device" || exit 1
  fi
  ;;
flipped-bit)
  "$pumpd" "$(scene one "$tmp/one" false 1)" > "$tmp/one.log" 2>&1 || fail "the run failed"
  # The initial tip's x (0.05, a vertex of the crack polyline), its lowest mantissa bit flipped.
  python3 - "$tmp/one/checkpoint.h5" <<'END' || fail "the checkpoint holds no 0.05"
import struct, sys
data = bytearray(open(sys.argv[1], 'rb').read())
at = data.find(struct.pack('<d', 0.05))
if at < 0:
    sys.exit(1)
data[at] ^= 1
open(sys.argv[1], 'wb').write(data)
END
  "$here/expect_error.sh" "$pumpd" "$(scene one-resumed "$tmp/one" true 2)" -- \
    "^pumpd: error in .*: Resume = true: cycle checkpoint: $tmp/one/checkpoint\.h5: its contents do not match their checksum" || exit 1
  ;;
small-disk)
  mkdir -p "$mnt"
  mount -t tmpfs -o size=40m tmpfs "$mnt" 2>/dev/null || { echo "no tmpfs (not root): skipped"; exit 77; }
  cat > "$tmp/edge.prm" <<END
include prm/pd-edge-crack.prm
subsection Scene
  set Output directory = $mnt/edge
end
subsection Edge crack
  set Load steps = 10000
end
END
  "$here/expect_error.sh" "$pumpd" "$tmp/edge.prm" -- \
    "Output interval = 1: with Load steps = 10000 the run would write about 4[0-9]\.[0-9] GB of VTU files \(1e\+04 of about 4\.[0-9]+ MB\), more than half of the 4[0-9](\.[0-9]+)? MB free in $mnt/edge" || exit 1
  ;;
*)
  fail "unknown mode $mode"
  ;;
esac
