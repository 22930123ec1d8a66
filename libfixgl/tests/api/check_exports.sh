#!/usr/bin/env bash
# check_exports.sh LIBRARY [--sanitized]
#
# Checks the public face of the shared library:
#  - every defined dynamic symbol starts with gl, OSMesa or fixgl;
#  - the OSMesa entry points that programs call are all exported;
#  - DT_NEEDED lists only libc, libm, libpthread and the dynamic loader
#    (with --sanitized: also the sanitizer runtimes the build links in);
#  - a soname is set;
#  - the gl* symbols are exactly the functions of main/api_list.h (the table
#    OSMesaGetProcAddress answers from).
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 LIBRARY [--sanitized]" >&2
  exit 2
fi
lib=$1
sanitized=${2:-}
status=0
fail() { echo "FAIL: $*"; status=1; }

[[ -f $lib ]] || { echo "FAIL: no such file: $lib"; exit 1; }

# Defined dynamic symbols, without version suffixes.
symbols=$(nm -D --defined-only --format=posix "$lib" | awk '{ sub(/@.*/, "", $1); print $1 }')
count=$(printf '%s\n' "$symbols" | grep -c . || true)
echo "$count defined dynamic symbol(s)"

bad=$(printf '%s\n' "$symbols" | grep -v -E '^(gl|OSMesa|fixgl)' | grep . || true)
if [[ -n $bad ]]; then
  fail "symbols outside gl*/OSMesa*/fixgl* are exported:"
  printf '  %s\n' $bad
fi

for sym in OSMesaCreateContext OSMesaCreateContextExt OSMesaDestroyContext \
           OSMesaMakeCurrent OSMesaGetCurrentContext OSMesaPixelStore \
           OSMesaGetIntegerv OSMesaGetDepthBuffer OSMesaGetColorBuffer \
           OSMesaGetProcAddress; do
  # a here-string, not a pipe: grep -q stops reading at the first match,
  # and under pipefail the writer's SIGPIPE would fail the check
  grep -qx "$sym" <<<"$symbols" || fail "$sym is not exported"
done

api_list=$(dirname "$0")/../../main/api_list.h
listed=$(sed -n 's/^FGL_API(\(gl[A-Za-z0-9_]*\))$/\1/p' "$api_list" | sort)
exported=$(printf '%s\n' "$symbols" | grep -E '^gl' | sort)
if [[ "$listed" != "$exported" ]]; then
  fail "exported gl* symbols and main/api_list.h differ (< exported only, > listed only):"
  diff <(printf '%s\n' "$exported") <(printf '%s\n' "$listed") | grep '^[<>]' | sed 's/^/  /'
fi
echo "$(printf '%s\n' "$listed" | grep -c .) gl* entry points, all in main/api_list.h"

# Libraries the dynamic linker must load with this one.
allowed='^(libc\.so\.6|libm\.so\.6|libpthread\.so\.0|ld-linux-x86-64\.so\.2|ld-linux-aarch64\.so\.1)$'
if [[ $sanitized == --sanitized ]]; then
  allowed='^(libc\.so\.6|libm\.so\.6|libpthread\.so\.0|ld-linux-x86-64\.so\.2|ld-linux-aarch64\.so\.1|libasan\.so\.[0-9]+|libubsan\.so\.[0-9]+|libgcc_s\.so\.1)$'
fi
dynamic=$(readelf -d -W "$lib")
needed=$(printf '%s\n' "$dynamic" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "DT_NEEDED: ${needed:-(none)}" | tr '\n' ' '
echo
for n in $needed; do
  [[ $n =~ $allowed ]] || fail "unexpected DT_NEEDED: $n"
done

soname=$(printf '%s\n' "$dynamic" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
if [[ -z $soname ]]; then
  fail "no soname set"
else
  echo "soname: $soname"
fi

[[ $status -eq 0 ]] && echo "PASS"
exit $status
