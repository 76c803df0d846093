#!/bin/bash
# Issue #19 "Scale": import time and peak memory of a long meter log, and the time a workspace holding it takes to
# show a window that answers. Prints one line per measurement, with the load average (the machine is shared).
#
# usage: scripts/bench/power-scale.sh [BUILD_DIR] [SAMPLES...]       (default: build 1e7 1e8)
#   BENCH_DIR=/tmp/psd        where the synthetic CSVs (benchscope-cli synth-power, ~20 B per sample) and
#                             workspaces go
#   BENCH_BASE_CLI, BENCH_BASE_GUI  binaries of another build (e.g. main before the change): measured alternately
#                             with this build's, as the reference for the ratios
#   BENCH_REPEAT=2            repetitions per measurement (mean ± SD, n printed)
set -u
BUILD=${1:-build}; shift || true
SIZES=("$@"); [ ${#SIZES[@]} -eq 0 ] && SIZES=(1e7 1e8)
DIR=${BENCH_DIR:-/tmp/psd}; REPEAT=${BENCH_REPEAT:-2}
CLI=$BUILD/app/cli/benchscope-cli; GUI=$BUILD/app/gui/benchscope
mkdir -p "$DIR"
echo "power-scale benchmark: $(date -u +%FT%TZ), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"

# /usr/bin/time -f '%e %M' -> "seconds peak_kB"; the command's stdout goes to $DIR/last.out
timed() { /usr/bin/time -f '%e %M' -o "$DIR/time.txt" "$@" >"$DIR/last.out" 2>"$DIR/last.err"; local rc=$?; cat "$DIR/time.txt" | tail -1; return $rc; }
stats() { python3 -c 'import sys,statistics as s; v=[float(x) for x in sys.argv[1:]]; print(f"{s.mean(v):.2f} ± {s.stdev(v) if len(v)>1 else 0:.2f} (n={len(v)})")' "$@"; }

import_once() {  # BIN N -> "seconds peakMB" or "failed: reason"
  local bin=$1 n=$2 ws="$DIR/bench-$2.bsw"
  rm -f "$ws" "$ws-wal" "$ws-shm"
  local r; r=$(timed "$bin" import --quiet "$ws" "$DIR/synth-$n.csv")
  if [ $? -ne 0 ]; then echo "failed: $(head -c 160 "$DIR/last.err" | tr '\n' ' ')"; return; fi
  set -- $r; echo "$1 $(( $2 / 1024 ))"
}

open_once() {  # GUI N -> "shown_ms answering_ms loaded_ms peakMB" (loaded: samples in the views)
  local gui=$1 ws="$DIR/bench-$2.bsw"
  local r; r=$(timed xvfb-run -a -s "-screen 0 1600x1000x24" "$gui" --startup-time "$ws")
  local line; line=$(grep '^startup:' "$DIR/last.out")
  set -- $r
  echo "$(echo "$line" | grep -o '[0-9]* ms' | tr -d ' ms' | tr '\n' ' ')$(( $2 / 1024 ))"
}

for n in "${SIZES[@]}"; do
  N=$(python3 -c "print(int(float('$n')))")
  [ -s "$DIR/synth-$N.csv" ] || "$CLI" synth-power --out "$DIR/synth-$N.csv" --samples "$N" >/dev/null
  MB=$(( N * 16 / 1000000 ))
  echo "== $N samples ($(( $(stat -L -c %s "$DIR/synth-$N.csv") / 1000000 )) MB of CSV; time + one channel = $MB MB of samples, 2x = $(( 2 * MB )) MB)"
  for who in base new; do eval "IMP_$who=()"; eval "RSS_$who=()"; done
  for ((i = 0; i < REPEAT; ++i)); do
    for who in base new; do  # alternate, so a load change on the shared machine hits both
      bin=$CLI; [ $who = base ] && { [ -n "${BENCH_BASE_CLI:-}" ] || continue; bin=$BENCH_BASE_CLI; }
      out=$(import_once "$bin" "$N")
      echo "  import ($who) run $((i + 1)): ${out} (s, peak MB) load $(cut -d' ' -f1 /proc/loadavg)"
      case $out in failed*) ;; *) set -- $out; eval "IMP_$who+=($1)"; eval "RSS_$who+=($2)";; esac
    done
  done
  # The new build's workspace stays for the open test (the last import above was this build's).
  for who in base new; do
    eval "t=(\"\${IMP_$who[@]:-}\")"; eval "m=(\"\${RSS_$who[@]:-}\")"
    [ -n "${t[0]:-}" ] && echo "  import ($who): $(stats "${t[@]}") s, peak RSS $(stats "${m[@]}") MB = $(python3 -c "print(f'{${m[0]}/$MB:.2f}')")x the samples"
  done
  if [ -x "$GUI" ]; then
    for ((i = 0; i < REPEAT; ++i)); do
      set -- $(open_once "$GUI" "$N")
      echo "  open (new) run $((i + 1)): window shown ${1} ms, answering ${2} ms, samples in the views ${3} ms, peak RSS ${4} MB, load $(cut -d' ' -f1 /proc/loadavg)"
    done
  fi
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
