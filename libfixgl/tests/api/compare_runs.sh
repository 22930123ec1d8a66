#!/usr/bin/env bash
# compare_runs.sh ORACLE_EXE FIXGL_EXE WORKDIR
#
# Runs one test program built twice, against the system OSMesa (the oracle)
# and against libfixgl, and fails unless both exit 0 and their outputs are
# identical byte for byte. Each program gets one argument, the path of an
# output file it may write (dropin_demo writes its PPM there); its stdout is
# a transcript. Both the transcripts and the output files must match.
#
# Under AddressSanitizer the oracle run does not report leaks: Mesa leaks by
# design and is not ours. The fixgl run keeps leak detection on.
set -euo pipefail

if [[ $# -ne 3 ]]; then
  echo "usage: $0 ORACLE_EXE FIXGL_EXE WORKDIR" >&2
  exit 2
fi
oracle=$1 fixgl=$2
work=$3/$(basename "$fixgl").cmp
rm -rf "$work"
mkdir -p "$work"

status=0
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  "$oracle" "$work/oracle.out" >"$work/oracle.txt" || { echo "FAIL: oracle run ($oracle) exited $?"; status=1; }
"$fixgl" "$work/fixgl.out" >"$work/fixgl.txt" || { echo "FAIL: fixgl run ($fixgl) exited $?"; status=1; }

if ! diff -u --label oracle --label fixgl "$work/oracle.txt" "$work/fixgl.txt"; then
  echo "FAIL: transcripts differ (oracle -, fixgl +)"
  status=1
fi

if [[ -e $work/oracle.out || -e $work/fixgl.out ]]; then
  if [[ ! -e $work/oracle.out || ! -e $work/fixgl.out ]]; then
    echo "FAIL: only one run wrote its output file"
    status=1
  elif ! cmp -s "$work/oracle.out" "$work/fixgl.out"; then
    ndiff=$(cmp -l "$work/oracle.out" "$work/fixgl.out" 2>/dev/null | wc -l || true)
    echo "FAIL: output files differ in $ndiff byte(s): $work/oracle.out $work/fixgl.out"
    status=1
  else
    echo "output files identical ($(stat -c %s "$work/fixgl.out") bytes)"
  fi
fi
[[ $status -eq 0 ]] && echo "PASS: fixgl matches the oracle"
exit $status
