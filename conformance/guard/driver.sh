#!/usr/bin/env bash
# driver.sh - the ./fixgl driver keeps stdout for the command's own output
# (suite guard): apt-get, meson and ninja replaced by stubs that print on
# stdout (one package reported missing, so apt-get runs too), then
#   ./fixgl conform --list   stdout is exactly fixgl-conform's list
#   ./fixgl run echo ...     stdout is exactly the program's
#   ./fixgl help             the usage, on stdout
# and the stubs' lines are found on stderr.
#
#   driver.sh SOURCE_DIR BUILD_DIR
set -uo pipefail

src=$1 build=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fixgl-driver.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

mkdir "$tmp/bin"
stub() {  # NAME BODY
  printf '#!/bin/sh\n%s\n' "$2" >"$tmp/bin/$1"
  chmod +x "$tmp/bin/$1"
}
# every package installed but cmake; apt-get, meson and ninja talk on stdout
stub dpkg-query 'case "$*" in *" cmake") echo "unknown ok not-installed";; *) echo "install ok installed";; esac'
stub apt-get 'echo "STUB apt-get $*"; echo "Reading package lists..."; exit 0'
stub sudo 'exec "$@"'
stub meson 'echo "STUB meson $*"; exit 0'
stub ninja 'echo "STUB ninja: Entering directory $2"; echo "ninja: no work to do."; exit 0'
export PATH=$tmp/bin:$PATH FIXGL_BUILD_DIR=$build
unset CI

# 1. conform --list: the list alone (what fixgl-conform prints itself)
"$build/conformance/fixgl-conform" --random 1000 --random-lit 1000 --random-raster 1000 \
  --random-tex 1000 --random-shading 1000 --seed 1 --known "$src/conformance/known-differences.txt" \
  --list >"$tmp/want" 2>/dev/null || fail "fixgl-conform --list: exit $?"
"$src/fixgl" conform --list >"$tmp/out" 2>"$tmp/err" || fail "./fixgl conform --list: exit $?"
if [[ ! -s $tmp/want ]]; then
  fail "fixgl-conform --list printed nothing"
elif cmp -s "$tmp/want" "$tmp/out"; then
  ok "./fixgl conform --list > FILE holds the list alone ($(wc -l <"$tmp/out") lines)"
else
  fail "./fixgl conform --list: stdout is not the list alone:"; diff "$tmp/want" "$tmp/out" | head -8
fi
for w in "STUB apt-get" "STUB ninja" "fixgl: building" "fixgl: installing missing packages: cmake"; do
  grep -qF "$w" "$tmp/err" || fail "./fixgl conform: no '$w' on stderr"
done
grep -q STUB "$tmp/out" && fail "./fixgl conform: a build line on stdout"

# 2. run: the program's stdout alone (without libGL.so.1, -Dglx=disabled:
#    an error on stderr and nothing on stdout)
out=$("$src/fixgl" run echo one two 2>"$tmp/err")
rc=$?
if [[ -e $build/libfixgl/libgl/libGL.so.1 ]]; then
  [[ $rc -eq 0 && $out == "one two" ]] && ok "./fixgl run echo: stdout alone" \
    || fail "./fixgl run echo: exit $rc, stdout '$out'"
else
  [[ $rc -ne 0 && -z $out ]] && grep -q 'libGL.so.1 was not built' "$tmp/err" \
    && ok "./fixgl run without libGL.so.1: the error on stderr alone" \
    || fail "./fixgl run without libGL.so.1: exit $rc, stdout '$out'"
fi
grep -qF "STUB ninja" "$tmp/err" || fail "./fixgl run: the build's lines are not on stderr"

# 3. help on stdout, nothing on stderr
"$src/fixgl" help >"$tmp/out" 2>"$tmp/err"
grep -q '^usage: ./fixgl COMMAND' "$tmp/out" && [[ ! -s $tmp/err ]] && ok "./fixgl help" || fail "./fixgl help"

echo "failures: $failures"
[[ $failures -eq 0 ]]
