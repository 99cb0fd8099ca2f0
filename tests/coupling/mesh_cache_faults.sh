#!/usr/bin/env bash
# mesh_cache_faults.sh <pumpd> <scene.prm>: a damaged entry of the mesh cache (PUMPD_MESH_CACHE) is
# dropped and the .geo meshed again. The scene (a .geo, no output directory) is run once to fill
# the cache; then its entry is damaged, and each run after must end as the first did (its end line
# but the time) with the cache entry written again as it was. Damages:
#   tangled    two interior nodes swap places (the cells around them tangle);
#   on-node    an interior node moved onto another;
#   flat       every node's y set to 0 (cells of zero area);
#   truncated  the file cut in half;
#   binary     the header says binary (file-type 1).
set -u
pumpd=$1 scene=$2
tmp=$(mktemp -d /tmp/pumpd-mesh-cache-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
export PUMPD_MESH_CACHE=$tmp/cache
unset PUMPD_GMSH

# run <name>: pumpd on the scene; its end line without the time into $tmp/<name>.end.
run() {
  "$pumpd" "$scene" > "$tmp/$1.out" 2> "$tmp/$1.err"
  local status=$?
  [ $status -eq 0 ] || fail "$1: exit $status: $(cat "$tmp/$1.err")"
  grep '^end: ' "$tmp/$1.out" | sed 's/, [0-9.e+-]* s$//' > "$tmp/$1.end"
  [ -s "$tmp/$1.end" ] || fail "$1: no end line"
}

run first
entries=("$PUMPD_MESH_CACHE"/*.msh)
[ ${#entries[@]} -eq 1 ] && [ -f "${entries[0]}" ] || fail "the first run left no single cache entry"
entry=${entries[0]}
cp "$entry" "$tmp/good.msh"
echo "first run: $(cat "$tmp/first.end")"

# The interior nodes are the last ones of a gmsh mesh of a transfinite surface.
nodes=$(awk '/^\$Nodes/ { getline; print; exit }' "$tmp/good.msh")
damage() {
  case $1 in
    tangled) awk -v a=$((nodes - 1)) -v b=$((nodes - 12)) '
               FNR == NR { if ($1 == a || $1 == b) xy[$1] = $2 " " $3; next }
               /^\$Nodes/ { in_nodes = 1 } /^\$EndNodes/ { in_nodes = 0 }
               in_nodes && $1 == a { print a, xy[b], $4; next }
               in_nodes && $1 == b { print b, xy[a], $4; next } { print }' "$tmp/good.msh" "$tmp/good.msh" ;;
    on-node) awk -v a=$((nodes - 1)) -v b=$((nodes - 2)) '
               FNR == NR { if ($1 == b) xy = $2 " " $3; next }
               /^\$Nodes/ { in_nodes = 1 } /^\$EndNodes/ { in_nodes = 0 }
               in_nodes && $1 == a { print a, xy, $4; next } { print }' "$tmp/good.msh" "$tmp/good.msh" ;;
    flat) awk '/^\$Nodes/ { in_nodes = 1; print; getline; print; next } /^\$EndNodes/ { in_nodes = 0 }
               in_nodes { $3 = 0 } { print }' "$tmp/good.msh" ;;
    truncated) head -c $(($(wc -c < "$tmp/good.msh") / 2)) "$tmp/good.msh" ;;
    binary) sed '2s/^2\.2 0 8$/2.2 1 8/' "$tmp/good.msh" ;;
  esac
}
for d in tangled on-node flat truncated binary; do
  damage $d > "$entry"
  cmp -s "$entry" "$tmp/good.msh" && fail "$d: the damage left the entry as it was"
  run $d
  cmp -s "$tmp/$d.end" "$tmp/first.end" || fail "$d: ends '$(cat "$tmp/$d.end")', not as the first run"
  cmp -s "$entry" "$tmp/good.msh" || fail "$d: the cache entry was not meshed again"
  echo "$d: meshed again, $(cat "$tmp/$d.end")"
done
