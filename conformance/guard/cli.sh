#!/usr/bin/env bash
# cli.sh - every program's command line (issue 20, part 3; suite guard):
# --version prints the library's version and the oracle's Mesa version,
# `--opt=value` means the same as `--opt value`, an unknown option is a
# usage error (exit 2).
#
#   cli.sh VERSION ORACLE NAME=PATH...
#
# NAME selects the checks of that program (fixgl-view, fixgl-conform, ...).
set -uo pipefail

version=$1 oracle=$2
shift 2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fixgl-cli.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

# same NAME CMD_A... -- CMD_B...: both succeed with the same, non-empty stdout
same() {
  local name=$1 a=() b=()
  shift
  while [[ $1 != -- ]]; do a+=("$1"); shift; done
  shift
  b=("$@")
  if ! "${a[@]}" >"$tmp/a" 2>"$tmp/ea"; then fail "$name: ${a[*]}: exit $?"; sed 's/^/  /' "$tmp/ea" | tail -5; return; fi
  if ! "${b[@]}" >"$tmp/b" 2>"$tmp/eb"; then fail "$name: ${b[*]}: exit $?"; sed 's/^/  /' "$tmp/eb" | tail -5; return; fi
  if [[ ! -s $tmp/a ]]; then fail "$name: ${a[*]}: no output"; return; fi
  if ! cmp -s "$tmp/a" "$tmp/b"; then fail "$name: '${a[*]}' and '${b[*]}' differ"; return; fi
  ok "$name: --opt=value as --opt value"
}

# usage_error NAME CMD...: exit status 2 and a message on stderr
usage_error() {
  local name=$1 rc
  shift
  "$@" >"$tmp/out" 2>"$tmp/err"
  rc=$?
  if [[ $rc -ne 2 || ! -s $tmp/err ]]; then
    fail "$name: '$*' gives exit $rc (want 2 with a message)"
  else
    ok "$name: '${*: -1}' refused"
  fi
}

for arg in "$@"; do
  name=${arg%%=*} exe=${arg#*=}
  # --version: one line, the program, fixgl's version, the oracle's
  out=$("$exe" --version 2>&1)
  want="$name (fixgl) $version, checked against $oracle (OSMesa, llvmpipe)"
  if [[ $out != "$want" ]]; then
    fail "$name --version: '$out' (want '$want')"
  else
    ok "$name --version"
  fi
  "$exe" --help >"$tmp/help" 2>&1 || fail "$name --help: exit $?"
  grep -q -- '--version' "$tmp/help" || fail "$name --help does not name --version"
  usage_error "$name" "$exe" --no-such-option

  case $name in
    fixgl-view)
      # the same frame both ways (stdout names the file written)
      if "$exe" --headless --size=40x30 --shade=flat --yaw=10 --out="$tmp/v1.png" >/dev/null 2>&1 \
         && "$exe" --headless --size 40x30 --shade flat --yaw 10 --out "$tmp/v2.png" >/dev/null 2>&1 \
         && [[ -s $tmp/v1.png ]] && cmp -s "$tmp/v1.png" "$tmp/v2.png"; then
        ok "$name: --opt=value as --opt value (the same frame)"
      else
        fail "$name: --size=40x30 ... and --size 40x30 ... do not give the same frame"
      fi
      # and a frame that differs when an option's value is not taken
      "$exe" --headless --size=40x30 --shade=flat --yaw=100 --out="$tmp/v3.png" >/dev/null 2>&1
      cmp -s "$tmp/v1.png" "$tmp/v3.png" && fail "$name: --yaw=100 drew the --yaw=10 frame"
      usage_error "$name" "$exe" --headless --size=1x1
      usage_error "$name" "$exe" --headless --size
      ;;
    fixgl-conform)
      same "$name" "$exe" --list --no-random --tag=core --case='core/fill*' \
        -- "$exe" --list --no-random --tag core --case 'core/fill*'
      n=$(wc -l <"$tmp/a")
      [[ $n -ge 2 ]] && ! grep -qv '^core/fill' "$tmp/a" \
        || fail "$name: --case=core/fill* selected something else ($n lines)"
      usage_error "$name" "$exe" --list --seed
      ;;
    fixgl-fuzz)
      same "$name" "$exe" --print=3 --calls=20 -- "$exe" --print 3 --calls 20
      ;;
    fixgl-bench-fixgl | fixgl-bench-osmesa)
      "$exe" --seconds=0.01 lines >"$tmp/bench" 2>&1 && grep -q 'lines' "$tmp/bench" \
        && ok "$name --seconds=0.01 lines" || { fail "$name --seconds=0.01 lines"; tail -3 "$tmp/bench"; }
      usage_error "$name" "$exe" --seconds=x
      ;;
    fixgl-bench-vertex)
      "$exe" --seconds=0.01 color >"$tmp/bench" 2>&1 && grep -q 'color' "$tmp/bench" \
        && ok "$name --seconds=0.01 color" || { fail "$name --seconds=0.01 color"; tail -3 "$tmp/bench"; }
      usage_error "$name" "$exe" --seconds=0
      ;;
    fixgl-render-*)
      "$exe" --out="$tmp/r1" core/fill_rule_square && "$exe" --out "$tmp/r2" core/fill_rule_square \
        && cmp -s "$tmp/r1" "$tmp/r2" && ok "$name: --out=FILE" || fail "$name: --out=FILE and --out FILE differ"
      ;;
    fixgl-fuzz-exec-*)
      "$exe" --missing >/dev/null || fail "$name --missing: exit $?"
      usage_error "$name" "$exe" --missing extra
      ;;
  esac
done

echo "failures: $failures"
[[ $failures -eq 0 ]]
