#!/usr/bin/env bash
# Opens a written dashboard (REPORTS/index.html) from the file system in headless Chromium, lets the
# page's own self-test (#selftest) run (it starts the replay and checks every section), and fails
# unless the page reports no script errors, every section filled, the plots loaded and the replay
# moving (and, with EMINI_REQUIRE_ORACLE set, the oracle's points and maps present; with
# EMINI_REQUIRE_BENCH set, the benchmark's table in the Speed section; with EMINI_REQUIRE_SLEEPING set,
# sleeping bodies drawn in a replay and the run with sleeping on summarised; with EMINI_REQUIRE_NUDGED set, the
# nudged run summarised; with EMINI_REQUIRE_WORKERS set, the run at two worker threads summarised; with EMINI_REQUIRE_DETAILS set,
# the comparison's summary table, a yellow bounded-energy cell and a landscape drawn). Installs Debian's
# chromium first when /usr/bin/chromium is missing.
#   harness/src/test/browser/check-dashboard.sh REPORTS [SCREENSHOT.png]
set -euo pipefail
reports=$(cd "$1" && pwd)
shot=${2:-}
CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$CHROMIUM" ]; then
  echo "check-dashboard: installing Debian's chromium (once)" >&2
  if [ "$(id -u)" = 0 ]; then SUDO=(); else SUDO=(sudo); fi
  "${SUDO[@]}" apt-get install -y chromium >/dev/null 2>&1 || { "${SUDO[@]}" apt-get update >/dev/null && "${SUDO[@]}" apt-get install -y chromium >/dev/null; }
fi
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
# Flags that work on a machine with no network (see README, Testing the dashboard).
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --user-data-dir="$profile" --allow-file-access-from-files)
dom=$(timeout 120 "$CHROMIUM" "${flags[@]}" --virtual-time-budget=8000 --dump-dom "file://$reports/index.html#selftest" 2>/dev/null)
result=$(printf '%s' "$dom" | sed -n 's/.*<pre id="selftest-result"[^>]*>\(.*\)<\/pre>.*/\1/p' | sed 's/&quot;/"/g; s/&amp;/\&/g')
if [ -z "$result" ]; then
  echo "check-dashboard: the page's self-test did not report (script error or not run)" >&2
  exit 1
fi
echo "check-dashboard: $result"
if [ -n "$shot" ]; then
  timeout 120 "$CHROMIUM" "${flags[@]}" --window-size=1200,2400 --screenshot="$shot" "file://$reports/index.html" >/dev/null 2>&1 || true
fi
# With EMINI_REQUIRE_ORACLE set (./emini test sets it) the page must also show the pymunk oracle's
# sweep points and stability maps.
if [ -n "${EMINI_REQUIRE_ORACLE:-}" ]; then
  case "$result" in
    *'"oraclePoints":0,'*|*'"oraclePoints":0}'*|*'"oracleMapTables":0,'*)
      echo "check-dashboard: FAILED: no pymunk sweep points or stability maps on the page" >&2; exit 1 ;;
  esac
fi
# With EMINI_REQUIRE_BENCH set the reports folder holds a benchmark report: the Speed section must show it.
if [ -n "${EMINI_REQUIRE_BENCH:-}" ]; then
  case "$result" in
    *'"bench":false'*|*'"speedRows":0'*)
      echo "check-dashboard: FAILED: no benchmark table in the Speed section" >&2; exit 1 ;;
  esac
fi
# With EMINI_REQUIRE_SLEEPING set the reports hold a scene that lets bodies sleep and the run with
# sleeping forced on: the replay must draw sleeping bodies and the verdicts must summarise that run.
if [ -n "${EMINI_REQUIRE_SLEEPING:-}" ]; then
  case "$result" in
    *'"sleepingReplays":0'*|*'"sleepingSummary":false'*)
      echo "check-dashboard: FAILED: no sleeping replay or no summary of the run with sleeping on" >&2; exit 1 ;;
  esac
fi
# With EMINI_REQUIRE_NUDGED set the reports hold a nudged run (reports/nudged/*): the verdicts must summarise it.
if [ -n "${EMINI_REQUIRE_NUDGED:-}" ]; then
  case "$result" in
    *'"nudgedSummaries":'[1-9]*) ;;
    *) echo "check-dashboard: FAILED: no summary of the nudged run" >&2; exit 1 ;;
  esac
fi
# With EMINI_REQUIRE_WORKERS set the reports hold a run at two worker threads (reports/workers/x2): the verdicts
# must say how many of its scenes are bit-identical to the run as written.
if [ -n "${EMINI_REQUIRE_WORKERS:-}" ] && [[ "$result" != *'"workersSummary":true'* ]]; then
  echo "check-dashboard: FAILED: no summary of the run at two worker threads" >&2; exit 1
fi
# With EMINI_REQUIRE_DETAILS set (./emini test: the smoke reports hold a comparison, a stability map with a
# bounded energy error and a scene with a landscape): the comparison's closer-to-the-truth table and
# filter, a bounded-energy cell painted yellow (#ffe08a) and a landscape segment drawn on the replay's canvas.
if [ -n "${EMINI_REQUIRE_DETAILS:-}" ]; then
  case "$result" in
    *'"closerRows":'[2-9]*|*'"closerRows":'[1-9][0-9]*) ;;
    *) echo "check-dashboard: FAILED: no closer-to-the-truth table in the comparison" >&2; exit 1 ;;
  esac
  case "$result" in
    *'"energyErrorColour":"rgb(255, 224, 138)"'*) ;;
    *) echo "check-dashboard: FAILED: no bounded-energy cell painted yellow in the stability maps" >&2; exit 1 ;;
  esac
  case "$result" in
    *'"landscapeReplays":0'*|*'"landscapePixels":0'*) echo "check-dashboard: FAILED: no landscape segment drawn in a replay" >&2; exit 1 ;;
    *'"landscapePixels":'*) ;;
    *) echo "check-dashboard: FAILED: no replay with a landscape" >&2; exit 1 ;;
  esac
fi
case "$result" in
  *'"ok":true'*) exit 0 ;;
  *) echo "check-dashboard: FAILED" >&2; exit 1 ;;
esac
