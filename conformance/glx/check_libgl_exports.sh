#!/usr/bin/env bash
# check_libgl_exports.sh LIBGL LIBFIXGL [--sanitized]
#
# The public face of libGL.so.1 (libfixgl/libgl/):
#  - every defined dynamic symbol starts with gl, glX, OSMesa or fixgl;
#  - the gl* entry points are exactly libfixgl.so's;
#  - the GLX 1.4 functions (issue 20's list) and the swap-control ones are
#    exported;
#  - soname libGL.so.1; DT_NEEDED: libc, libm, libpthread, libX11, libXext
#    (and the sanitizer runtimes of a sanitized build).
set -euo pipefail

if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: $0 LIBGL LIBFIXGL [--sanitized]" >&2
  exit 2
fi
lib=$1
fixgl=$2
sanitized=${3:-}
status=0
fail() { echo "FAIL: $*"; status=1; }
defined() { nm -D --defined-only --format=posix "$1" | awk '{ sub(/@.*/, "", $1); print $1 }'; }

[[ -f $lib && -f $fixgl ]] || { echo "FAIL: missing $lib or $fixgl"; exit 1; }
symbols=$(defined "$lib")
echo "$(printf '%s\n' "$symbols" | grep -c .) defined dynamic symbol(s)"

bad=$(printf '%s\n' "$symbols" | grep -v -E '^(gl|OSMesa|fixgl)' | grep . || true)
[[ -z $bad ]] || { fail "symbols outside gl*/glX*/OSMesa*/fixgl* are exported:"; printf '  %s\n' $bad; }

gl_here=$(printf '%s\n' "$symbols" | grep -E '^gl' | grep -v -E '^glX' | sort)
gl_fixgl=$(defined "$fixgl" | grep -E '^gl' | sort)
if [[ "$gl_here" != "$gl_fixgl" ]]; then
  fail "the gl* entry points of $lib and $fixgl differ (< libGL only, > libfixgl only):"
  diff <(printf '%s\n' "$gl_here") <(printf '%s\n' "$gl_fixgl") | grep '^[<>]' | sed 's/^/  /'
fi
echo "$(printf '%s\n' "$gl_here" | grep -c .) gl* entry points, libfixgl's"

for sym in glXQueryExtension glXQueryVersion glXGetClientString glXQueryServerString \
           glXQueryExtensionsString glXChooseVisual glXGetConfig glXChooseFBConfig \
           glXGetFBConfigs glXGetFBConfigAttrib glXGetVisualFromFBConfig glXCreateContext \
           glXCreateNewContext glXDestroyContext glXMakeCurrent glXMakeContextCurrent \
           glXGetCurrentContext glXGetCurrentDrawable glXGetCurrentDisplay glXSwapBuffers \
           glXWaitGL glXWaitX glXIsDirect glXUseXFont glXCreateWindow glXDestroyWindow \
           glXCreatePixmap glXDestroyPixmap glXCreateGLXPixmap glXDestroyGLXPixmap \
           glXGetProcAddress glXGetProcAddressARB glXSwapIntervalEXT glXSwapIntervalMESA \
           glXGetSwapIntervalMESA glXCreateContextAttribsARB glXCreatePbuffer glXDestroyPbuffer \
           glXQueryDrawable; do
  grep -qx "$sym" <<<"$symbols" || fail "$sym is not exported"
done
echo "$(printf '%s\n' "$symbols" | grep -c -E '^glX') glX* functions"

allowed='^(libc\.so\.6|libm\.so\.6|libpthread\.so\.0|libX11\.so\.6|libXext\.so\.6|ld-linux-x86-64\.so\.2|ld-linux-aarch64\.so\.1)$'
if [[ $sanitized == --sanitized ]]; then
  allowed='^(libc\.so\.6|libm\.so\.6|libpthread\.so\.0|libX11\.so\.6|libXext\.so\.6|ld-linux-x86-64\.so\.2|ld-linux-aarch64\.so\.1|libasan\.so\.[0-9]+|libubsan\.so\.[0-9]+|libgcc_s\.so\.1)$'
fi
dynamic=$(readelf -d -W "$lib")
needed=$(printf '%s\n' "$dynamic" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "DT_NEEDED: $(echo $needed)"
for n in $needed; do
  [[ $n =~ $allowed ]] || fail "unexpected DT_NEEDED: $n"
done
soname=$(printf '%s\n' "$dynamic" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[[ $soname == libGL.so.1 ]] || fail "soname is '$soname', not libGL.so.1"
echo "soname: $soname"

[[ $status -eq 0 ]] && echo "PASS"
exit $status
