#!/usr/bin/env bash
# check_alloc_routing.sh ARCHIVE - every member of libfixgl's object
# archive but fgl_alloc.c's leaves the C allocator alone: no undefined
# reference to malloc, calloc, realloc, free, strdup, strndup,
# aligned_alloc, posix_memalign, memalign or valloc (fgl_alloc.h: each
# allocation goes through fgl_malloc/fgl_calloc/fgl_realloc/fgl_free, so
# the suite robust can make any of them fail).
set -uo pipefail
archive=${1:?usage: check_alloc_routing.sh libfixgl_objs.a}
[[ -f $archive ]] || { echo "FAIL: no such archive: $archive"; exit 1; }
syms='^(malloc|calloc|realloc|free|strdup|strndup|aligned_alloc|posix_memalign|memalign|valloc)$'
undef=$(nm -A -u "$archive" 2>/dev/null) || { echo "FAIL: nm $archive"; exit 1; }
status=0 members=0
while read -r member sym; do
  members=1
  case $member in *fgl_alloc.c.o) continue ;; esac
  if [[ $sym =~ $syms ]]; then
    echo "FAIL: $member calls $sym directly"
    status=1
  fi
done < <(sed -E 's/^[^:]*:([^:]*):[[:space:]]*U[[:space:]]+(.*)$/\1 \2/' <<<"$undef")
if [[ $members -eq 0 ]]; then
  echo "FAIL: nm listed no undefined symbol in $archive"
  exit 1
fi
grep -q 'fgl_alloc.c.o:.*U malloc' <<<"$undef" || { echo "FAIL: fgl_alloc.c.o does not call malloc"; status=1; }
[[ $status -eq 0 ]] && echo "ok: only fgl_alloc.c.o calls the C allocator"
exit $status
