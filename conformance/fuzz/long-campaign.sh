#!/usr/bin/env bash
# long-campaign.sh - the long libFuzzer campaign of issue 18 §3 ("at least
# 10^8 calls in total across the differential fuzzer and libFuzzer, 0
# crashes, 0 hangs, 0 sanitizer reports, 0 unlisted differences"), run in
# chunks so that a finding stops it at once and the count is logged per
# chunk.  Resumable: the counts and the corpus stay in OUT, a second run
# adds to them.
#
#   conformance/fuzz/long-campaign.sh [--build DIR] [--out DIR] [--calls N]
#       [--chunk SECONDS] [--chunks K] [--extra-calls N] [--nice N]
#
#   --build DIR     the libFuzzer build (default build-fuzz: clang,
#                   -Dfuzzer=true -Db_sanitize=address,undefined, see
#                   conformance/fuzz/README.md); it is built here if needed
#   --out DIR       corpus, artifacts, logs, counts (default DIR/long-campaign)
#   --calls N       stop once the total reaches N calls (default 100000000)
#   --chunk S       seconds per libFuzzer process (-max_total_time, default 1200)
#   --chunks K      stop after K chunks of this invocation (default: no limit)
#   --extra-calls N calls run elsewhere (the differential campaign's "calls
#                   issued") counted towards the total; recorded in
#                   OUT/extra-calls.txt so later runs keep them
#   --nice N        niceness of the fuzzer (default 10)
#
# One libFuzzer process at a time (the machine is shared), seeded with the
# byte encodings of the differential campaign's first 50 streams
# (fixgl-libfuzzer-corpus) plus whatever earlier chunks added to the corpus.
# fixgl-libfuzzer appends "CALLS INPUTS" to OUT/calls.txt at each normal
# exit (FIXGL_FUZZ_CALLS_FILE, fz_libfuzzer.c).  Each chunk appends one line
# to OUT/campaign.log:
#   DATE commit=REV chunk=K exit=E seconds=S inputs=I calls=C calls/s=R total=T
# A chunk that exits non-zero (crash, sanitizer report, leak, -timeout=60
# hang, -rss_limit_mb=4096) stops the campaign with exit status 1; its log
# is OUT/chunk-K.log and the input that caused it is in OUT/artifacts/.
set -uo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/../.."

build=build-fuzz out= target=100000000 chunk=1200 max_chunks=0 extra=0 niceness=10
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --calls) target=$2; shift 2 ;;
    --chunk) chunk=$2; shift 2 ;;
    --chunks) max_chunks=$2; shift 2 ;;
    --extra-calls) extra=$2; shift 2 ;;
    --nice) niceness=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d'; exit 0 ;;
    *) echo "long-campaign.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
out=${out:-$build/long-campaign}

fuzzer=$build/conformance/fuzz/fixgl-libfuzzer
corpus_tool=$build/conformance/fuzz/fixgl-libfuzzer-corpus
if [[ ! -f $build/build.ninja ]]; then
  flags=-fno-sanitize-recover=all   # .ci/run's sanitize_flags
  env CC=clang CXX=clang++ meson setup "$build" -Dfuzzer=true -Davx512_kernels=false \
    -Db_sanitize=address,undefined -Db_lundef=false \
    -Dc_args="$flags" -Dcpp_args="$flags" -Dc_link_args="$flags" -Dcpp_link_args="$flags" \
    || exit 2
fi
ninja -C "$build" conformance/fuzz/fixgl-libfuzzer conformance/fuzz/fixgl-libfuzzer-corpus || exit 2

mkdir -p "$out/corpus" "$out/artifacts"
if [[ -z $(ls -A "$out/corpus") ]]; then
  "$corpus_tool" "$out/corpus" 50 || exit 2
fi
[[ $extra -gt 0 ]] && echo "$extra" >>"$out/extra-calls.txt"

# column $2 of file $1 summed (0 when the file does not exist yet)
sum_col() { if [[ -f $1 ]]; then awk -v k="$2" '{ s += $k } END { printf "%d\n", s }' "$1"; else echo 0; fi; }
sum_calls() { sum_col "$out/calls.txt" 1; }
sum_inputs() { sum_col "$out/calls.txt" 2; }
sum_extra() { sum_col "$out/extra-calls.txt" 1; }
total() { echo $(( $(sum_calls) + $(sum_extra) )); }

k=$(ls "$out" | grep -c '^chunk-.*\.log$')
# the sources the chunks of this invocation fuzz (a campaign that spans
# several commits says which calls each one took)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
done_chunks=0
echo "long-campaign: $(total) calls so far (libFuzzer $(sum_calls), elsewhere $(sum_extra)), target $target"
while [[ $(total) -lt $target ]]; do
  if [[ $max_chunks -gt 0 && $done_chunks -ge $max_chunks ]]; then
    echo "long-campaign: $max_chunks chunks run, $(total) of $target calls; run again to go on"
    exit 0
  fi
  k=$((k + 1))
  before_calls=$(sum_calls) before_inputs=$(sum_inputs)
  start=$SECONDS
  FIXGL_FUZZ_CALLS_FILE="$out/calls.txt" \
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    nice -n "$niceness" "$fuzzer" -max_total_time="$chunk" -timeout=60 -rss_limit_mb=4096 \
      -print_final_stats=1 -artifact_prefix="$out/artifacts/" "$out/corpus" \
      >"$out/chunk-$k.log" 2>&1
  rc=$?
  secs=$((SECONDS - start))
  calls=$(( $(sum_calls) - before_calls )) inputs=$(( $(sum_inputs) - before_inputs ))
  line="$(date -u +%FT%TZ) commit=$commit chunk=$k exit=$rc seconds=$secs inputs=$inputs calls=$calls calls/s=$(( calls / (secs > 0 ? secs : 1) )) total=$(total)"
  echo "$line" | tee -a "$out/campaign.log"
  done_chunks=$((done_chunks + 1))
  if [[ $rc -ne 0 ]]; then
    grep -v -E '^"|# Uses:' "$out/chunk-$k.log" | tail -n 60
    echo "long-campaign: chunk $k failed (exit $rc): log $out/chunk-$k.log, inputs in $out/artifacts/" >&2
    exit 1
  fi
done
echo "long-campaign: done, $(total) calls (libFuzzer $(sum_calls) in $(sum_inputs) inputs, elsewhere $(sum_extra)), 0 findings"
