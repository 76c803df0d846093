# SPDX-License-Identifier: GPL-3.0-or-later
# Wall time of each stage of `scripts/dev test` (sourced by scripts/dev and scripts/cross-test), so every CI log
# shows where the time goes. A stage is timed by `stage_begin NAME` ... `stage_end`; the records go to the file
# $BENCHSCOPE_STAGE_LOG (one "name<TAB>seconds<TAB>status" line each), which scripts/dev creates for the whole run
# and which the cross test, run as a child script, appends to. A stage that fails (set -e ends the script inside
# it) is recorded by the EXIT trap as "failed", so the summary of a red run still says which stage took how long.
# Without BENCHSCOPE_STAGE_LOG (the scripts run on their own) nothing is recorded or printed.

_stage_name="" _stage_t0=0

stage_begin() {
  [ -n "${BENCHSCOPE_STAGE_LOG:-}" ] || return 0
  _stage_name=$1
  _stage_t0=$(date +%s)
  echo "== stage $1: started $(date -u +%H:%M:%S) UTC"
}

stage_end() {
  [ -n "${BENCHSCOPE_STAGE_LOG:-}" ] && [ -n "$_stage_name" ] || return 0
  local s=$(($(date +%s) - _stage_t0))
  printf '%s\t%s\t%s\n' "$_stage_name" "$s" "${1:-ok}" >>"$BENCHSCOPE_STAGE_LOG"
  printf '== stage %s: %d min %02d s\n' "$_stage_name" $((s / 60)) $((s % 60))
  _stage_name=""
}

# The stage in progress when the script exits with an error: recorded as failed (called from an EXIT trap).
stage_abort() {
  local rc=$?
  [ "$rc" != 0 ] && [ -n "$_stage_name" ] && stage_end "failed (exit $rc)"
  return 0
}

# The compiler cache's state, one line: a cold run (the CI case) shows almost no hits.
stage_cache_state() {
  if command -v ccache >/dev/null 2>&1; then
    ccache --print-stats 2>/dev/null | awk -F'\t' '
      $1 == "direct_cache_hit" || $1 == "preprocessed_cache_hit" { hits += $2 }
      $1 == "cache_miss" { miss = $2 }
      $1 == "cache_size_kibibyte" { kib = $2 }
      END { printf "ccache: %d hits, %d misses this run (%.0f %% hits), cache %.1f GiB\n",
                   hits, miss, (hits + miss) ? 100 * hits / (hits + miss) : 0, kib / 1048576 }'
  else
    echo "ccache: not installed (every compile ran)"
  fi
}

# The table of stages, the total against the 45-minute target, and a warning past 60 minutes.
stage_summary() {
  [ -n "${BENCHSCOPE_STAGE_LOG:-}" ] && [ -f "$BENCHSCOPE_STAGE_LOG" ] || return 0
  echo "== stage times ($(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'))"
  awk -F'\t' '{ printf "  %-22s %4d min %02d s  %s\n", $1, $2 / 60, $2 % 60, $3; total += $2 }
    END { printf "  %-22s %4d min %02d s  (target: under 45 min on a cold 2-core machine)\n", "total", total / 60, total % 60 }' \
    "$BENCHSCOPE_STAGE_LOG"
  stage_cache_state
  local total
  total=$(awk -F'\t' '{ t += $2 } END { print t + 0 }' "$BENCHSCOPE_STAGE_LOG")
  if [ "$total" -gt 3600 ]; then
    echo "scripts/dev: WARNING: the test command ran $((total / 60)) min, past 60 min (CI stops at 90): see the stage times above" >&2
  fi
}
