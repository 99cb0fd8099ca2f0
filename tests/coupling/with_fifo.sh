#!/usr/bin/env bash
# with_fifo.sh <path> <command...>: runs the command with a FIFO (named pipe) at <path>, which no
# process writes to, and removes it after; the command's exit status is the script's.
set -u
fifo=$1; shift
mkdir -p "$(dirname "$fifo")" && rm -f "$fifo" && mkfifo "$fifo" || { echo "FAIL: cannot make the FIFO $fifo"; exit 1; }
"$@"
status=$?
rm -f "$fifo"
exit $status
