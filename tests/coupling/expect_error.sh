#!/usr/bin/env bash
# expect_error.sh <command...> -- <regex>: passes if the command fails (exit != 0) with exactly one
# line of output on stderr that matches the extended regex.
set -u
args=()
while [ "$1" != "--" ]; do args+=("$1"); shift; done
regex=$2
err=$("${args[@]}" 2>&1 >/dev/null)
status=$?
echo "exit $status: $err"
[ $status -ne 0 ] || { echo "FAIL: expected a non-zero exit"; exit 1; }
[ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || { echo "FAIL: expected one line"; exit 1; }
printf '%s\n' "$err" | grep -Eq "$regex" || { echo "FAIL: message does not match /$regex/"; exit 1; }
