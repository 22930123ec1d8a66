#!/usr/bin/env bash
# glext_exports.sh LIBRARY GLEXT_H NOT_YET
#
# Issue 19's export check: every function of the GL_VERSION_1_2 ..
# GL_VERSION_1_5 blocks of the system <GL/glext.h> is a defined dynamic
# symbol of LIBRARY (and so, by the exports test, in main/api_list.h, the
# table OSMesaGetProcAddress answers from), except those listed in NOT_YET
# (one name a line, # comments): the functions of features still to come.
# The list must be exact both ways: a listed function that is exported, or
# a listed name that is not in the header, fails too, so the list only
# shrinks and is empty when the work is done.
set -euo pipefail

if [[ $# -ne 3 ]]; then
  echo "usage: $0 LIBRARY GLEXT_H NOT_YET" >&2
  exit 2
fi
lib=$1 header=$2 not_yet=$3
status=0
fail() { echo "FAIL: $*"; status=1; }
[[ -f $lib ]] || { echo "FAIL: no such file: $lib"; exit 1; }
[[ -f $header ]] || { echo "FAIL: no such header: $header"; exit 1; }

exported=$(nm -D --defined-only --format=posix "$lib" | awk '{ sub(/@.*/, "", $1); print $1 }' | sort -u)
listed=$(sed -e 's/#.*//' -e 's/[[:space:]]//g' "$not_yet" | grep . | sort -u || true)
all=""
for v in 1_2 1_3 1_4 1_5; do
  # the GLAPI prototypes between "#ifndef GL_VERSION_x_y" and its "#endif"
  funcs=$(awk -v v="GL_VERSION_$v" '
      $0 == "#ifndef " v { on = 1 }
      on && /^GLAPI/ { if (match($0, /gl[A-Za-z0-9_]+ *\(/)) { s = substr($0, RSTART, RLENGTH); sub(/ *\($/, "", s); print s } }
      on && $0 ~ "^#endif /\\* " v " \\*/" { on = 0 }' "$header" | sort -u)
  n=$(printf '%s\n' "$funcs" | grep -c . || true)
  [[ $n -gt 0 ]] || fail "no GL_VERSION_$v functions found in $header"
  have=$(comm -12 <(printf '%s\n' "$funcs") <(printf '%s\n' "$exported") | grep -c . || true)
  echo "GL_VERSION_$v: $have of $n exported"
  all+="$funcs"$'\n'
done
all=$(printf '%s' "$all" | grep . | sort -u)

missing=$(comm -23 <(printf '%s\n' "$all") <(printf '%s\n' "$exported") | grep . || true)
unlisted=$(comm -23 <(printf '%s\n' "$missing") <(printf '%s\n' "$listed") | grep . || true)
[[ -z $unlisted ]] || { fail "not exported and not in $not_yet:"; printf '  %s\n' $unlisted; }
stale=$(comm -12 <(printf '%s\n' "$listed") <(printf '%s\n' "$exported") | grep . || true)
[[ -z $stale ]] || { fail "exported now, remove from $not_yet:"; printf '  %s\n' $stale; }
foreign=$(comm -23 <(printf '%s\n' "$listed") <(printf '%s\n' "$all") | grep . || true)
[[ -z $foreign ]] || { fail "listed in $not_yet but not a GL 1.2-1.5 function of the header:"; printf '  %s\n' $foreign; }
echo "$(printf '%s\n' "$missing" | grep -c . || true) of $(printf '%s\n' "$all" | grep -c .) GL 1.2-1.5 functions still to come (listed in $(basename "$not_yet"))"
[[ $status -eq 0 ]] && echo "PASS"
exit $status
