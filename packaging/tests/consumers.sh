#!/usr/bin/env bash
# consumers.sh - the suite packaging: fixgl as its users get it.
#
#   consumers.sh installed SOURCE_DIR BUILD_DIR PREFIX LIBDIR DATADIR
#       `meson install --destdir` of BUILD_DIR into a temporary directory,
#       then, from that tree alone, the consumer programs (consumer/: an
#       OSMesa triangle and a GLUT one) built three ways: cc with
#       pkg-config (PKG_CONFIG_SYSROOT_DIR/PKG_CONFIG_PATH into the
#       destdir), a meson project, a CMake project (find_package(fixgl
#       CONFIG) through CMAKE_PREFIX_PATH); each is run and its pixels
#       checked.  Also the installed files name no build path, and the
#       installed fixgl-view finds its bundled models.
#   consumers.sh subproject SOURCE_DIR
#       a parent meson project with subprojects/fixgl -> SOURCE_DIR, using
#       dependency('fixgl', fallback : 'fixgl') (fixgl's
#       meson.override_dependency), built without the suites, unoptimized
#       and with the portable kernels alone (-Dfixgl:simd_kernels=false:
#       the AVX2 kernels were 77 of its 89 s of compiling, even at -O0).
#
# Exit 0 when every check holds; each failure is printed.
set -uo pipefail

mode=$1 src=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fixgl-packaging.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

# run NAME OUTPUT_EXPECTED... -- CMD...: runs CMD, requires every
# expected line in its stdout.
expect() {
  local name=$1 out; shift
  local want=()
  while [[ $1 != -- ]]; do want+=("$1"); shift; done
  shift
  if ! out=$("$@" 2>"$tmp/stderr"); then
    fail "$name: exit status $? ($*)"; sed 's/^/  /' "$tmp/stderr"; return
  fi
  for w in "${want[@]}"; do
    grep -qxF -- "$w" <<<"$out" || { fail "$name: no line '$w' in its output:"; sed 's/^/  /' <<<"$out"; return; }
  done
  ok "$name"
}

# The pixels each consumer must draw (flat colours: exact on any renderer).
OSMESA_WANT=("center: 255 0 0" "corner: 0 0 255")
GLUT_WANT=("window: 80x60" "center: 0 255 0" "corner: 0 0 255")

check_triangle() {  # NAME BINARY
  expect "$1 (OSMesa)" "${OSMESA_WANT[@]}" -- "$2"
  # (grep -q on a pipe under pipefail: the writer may die of SIGPIPE)
  if grep -q 'NEEDED.*\[libGL\.so' <<<"$(readelf -d "$2")"; then
    fail "$1: links the system's libGL"
  fi
}
check_glut() {  # NAME BINARY
  expect "$1 (GLUT)" "${GLUT_WANT[@]}" -- env FIXGLUT_HEADLESS=1 FIXGLUT_FRAMES=1 "$2"
}

if [[ $mode == subproject ]]; then
  parent=$tmp/parent
  mkdir -p "$parent/subprojects"
  cp "$src/packaging/tests/subproject/meson.build" "$src/packaging/tests/consumer/triangle.c" "$parent/"
  ln -s "$src" "$parent/subprojects/fixgl"
  if ! meson setup "$parent/build" "$parent" --force-fallback-for=fixgl --buildtype=plain \
       -Dfixgl:conformance=disabled -Dfixgl:viewer=disabled -Dfixgl:glx=disabled \
       -Dfixgl:simd_kernels=false \
       >"$tmp/setup.log" 2>&1; then
    fail "meson setup of the parent project"; tail -20 "$tmp/setup.log"
  elif ! ninja -C "$parent/build" -j2 triangle >"$tmp/build.log" 2>&1; then
    fail "building the parent project"; tail -20 "$tmp/build.log"
  else
    # the library the triangle loads is the subproject's
    if grep -q "libfixgl.so.0 => $parent/build/subprojects/fixgl/" <<<"$(ldd "$parent/build/triangle")"; then
      ok "dependency('fixgl') is the subproject's libfixgl"
    else
      fail "dependency('fixgl') did not come from the subproject:"; ldd "$parent/build/triangle" | grep fixgl
    fi
    check_triangle "meson subproject" "$parent/build/triangle"
  fi
  echo "failures: $failures"
  [[ $failures -eq 0 ]]
  exit
fi

build=$3 prefix=$4 libdir=$5 datadir=$6 sanitize=${7:-none}
# a sanitized build's libraries need the consumers built with its runtime
san_flags=() meson_san=() cmake_san=()
if [[ $sanitize != none ]]; then
  san_flags=("-fsanitize=$sanitize")
  meson_san=("-Db_sanitize=$sanitize")
  cmake_san=("-DCMAKE_C_FLAGS=-fsanitize=$sanitize")
fi
root=$tmp/root
[[ $libdir == /* ]] || libdir=$prefix/$libdir
[[ $datadir == /* ]] || datadir=$prefix/$datadir
if ! meson install -C "$build" --no-rebuild --destdir "$root" >"$tmp/install.log" 2>&1; then
  fail "meson install --destdir"; tail -20 "$tmp/install.log"; exit 1
fi
lib=$root$libdir
export LD_LIBRARY_PATH=$lib

for f in "$lib/pkgconfig/fixgl.pc" "$lib/pkgconfig/fixglut.pc" \
         "$lib/cmake/fixgl/fixglConfig.cmake" "$lib/cmake/fixgl/fixglConfigVersion.cmake" \
         "$root$prefix/include/fixgl/fixgl/version.h" "$root$datadir/fixgl/models/teapot.obj"; do
  [[ -f $f ]] || fail "not installed: ${f#"$root"}"
done
# relocatable: no file of the packaging names the build or source tree
if grep -lF -e "$build" -e "$src" "$lib/pkgconfig/"*.pc "$lib/cmake/fixgl/"*.cmake; then
  fail "installed packaging files name the build or source tree"
fi
grep -qx 'Requires: fixgl' "$lib/pkgconfig/fixglut.pc" || fail "fixglut.pc does not require fixgl"

# 1. pkg-config
export PKG_CONFIG_SYSROOT_DIR=$root PKG_CONFIG_PATH=$lib/pkgconfig
cons=$src/packaging/tests/consumer
mkdir -p "$tmp/pc"
# shellcheck disable=SC2046
if cc -std=c11 -Wall -Werror "${san_flags[@]}" "$cons/triangle.c" -o "$tmp/pc/triangle" \
     $(pkg-config --cflags --libs fixgl) \
   && cc -std=c11 -Wall -Werror "${san_flags[@]}" "$cons/glut_triangle.c" -o "$tmp/pc/glut-triangle" \
     $(pkg-config --cflags --libs fixglut); then
  check_triangle "pkg-config" "$tmp/pc/triangle"
  check_glut "pkg-config" "$tmp/pc/glut-triangle"
else
  fail "cc with pkg-config"
fi

# 2. a meson project
cp -r "$cons" "$tmp/meson-src"
if meson setup "${meson_san[@]}" "$tmp/meson-build" "$tmp/meson-src" >"$tmp/meson.log" 2>&1 \
   && ninja -C "$tmp/meson-build" >>"$tmp/meson.log" 2>&1; then
  check_triangle "meson" "$tmp/meson-build/triangle"
  check_glut "meson" "$tmp/meson-build/glut-triangle"
else
  fail "meson consumer project"; tail -20 "$tmp/meson.log"
fi
unset PKG_CONFIG_SYSROOT_DIR PKG_CONFIG_PATH

# 3. a CMake project; the tree is moved first: the package must follow
mv "$root" "$tmp/moved"
root=$tmp/moved lib=$tmp/moved$libdir
export LD_LIBRARY_PATH=$lib
if cmake -S "$cons" -B "$tmp/cmake-build" -G Ninja -DCMAKE_PREFIX_PATH="$root$prefix" "${cmake_san[@]}" \
     >"$tmp/cmake.log" 2>&1 && cmake --build "$tmp/cmake-build" >>"$tmp/cmake.log" 2>&1; then
  check_triangle "cmake" "$tmp/cmake-build/triangle"
  check_glut "cmake" "$tmp/cmake-build/glut-triangle"
  grep -q "$root" "$tmp/cmake-build/build.ninja" || fail "cmake: the targets do not point into the moved tree"
else
  fail "cmake consumer project"; tail -20 "$tmp/cmake.log"
fi
# a version the package is not compatible with is refused
mkdir -p "$tmp/cmake-v9"
printf 'cmake_minimum_required(VERSION 3.16)\nproject(v C)\nfind_package(fixgl 9.0 CONFIG REQUIRED)\n' \
  >"$tmp/cmake-v9/CMakeLists.txt"
if cmake -S "$tmp/cmake-v9" -B "$tmp/cmake-v9/b" -DCMAKE_PREFIX_PATH="$root$prefix" >/dev/null 2>&1; then
  fail "cmake: find_package(fixgl 9.0) accepted version $(grep -o '"[0-9.]*"' "$lib/cmake/fixgl/fixglConfigVersion.cmake" | head -1)"
else
  ok "cmake: find_package(fixgl 9.0) refused"
fi

# 4. the installed viewer: its models under DATADIR/fixgl/models, named
#    there by --help, found (here in the moved tree) and drawn
view=$root$prefix/bin/fixgl-view
models=$root$datadir/fixgl/models
if [[ -x $view ]]; then
  help=$("$view" --help 2>&1)
  for m in teapot.obj sphere.ply torus.stl lowpoly.obj; do
    grep -qF "$models/$m" <<<"$help" || fail "installed fixgl-view --help does not name $models/$m"
  done
  grep -qF "$build" <<<"$help" && fail "installed fixgl-view --help names the build directory"
  if "$view" --headless --size 64x48 --out "$tmp/teapot.png" >"$tmp/view.log" 2>&1 \
     && "$view" --headless --size=64x48 --out="$tmp/sphere.png" sphere.ply >>"$tmp/view.log" 2>&1 \
     && [[ -s $tmp/teapot.png && -s $tmp/sphere.png ]]; then
    ok "installed fixgl-view draws its bundled models"
  else
    fail "installed fixgl-view"; tail -5 "$tmp/view.log"
  fi
else
  fail "fixgl-view is not installed"
fi

echo "failures: $failures"
[[ $failures -eq 0 ]]
