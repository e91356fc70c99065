#!/usr/bin/env bash
# The World Designer's check (./emini test runs it): writes the JVM's half of the parity test
# (ParityCheck: library scenes played on the JVM, every tick's state hashed over the floats' bits),
# opens the built page (designer/target/page/index.html#selftest) from the file system in headless
# Chromium, whose self-test plays the same scenes in the engine compiled to WebAssembly and compares
# tick by tick, times the first scene, and builds, saves (.phy) and reopens a world through the page's
# controls; then reads the page's saved .phy on the JVM (harness convert) and takes a screenshot.
# Fails unless the page reports ok. Uses Chromium as the dashboard's check does (installed when missing).
#   designer/src/test/browser/check-designer.sh [SCREENSHOT_DIR]
set -euo pipefail
cd "$(dirname "$0")/../../../.."
page=designer/target/page
check=designer/target/check
shots=${1:-$check}
[ -f "$page/index.html" ] && [ -f "$page/engine-wasm.js" ] || { echo "check-designer: no built page in $page (mvn install first)" >&2; exit 1; }
cp="designer/target/classes:harness/target/classes:engine/target/classes:harness/target/lib/*"
# Scenes: the ten pyramids (timed) and scenes with joints, springs, motors, a landscape, particles,
# events, multi-shapes and fast rotation.
java -cp "$cp" org.emini.designer.ParityCheck "$check" "${EMINI_DESIGNER_TICKS:-120}" 300 \
  scenarios/bench/pyramids-10x20.yaml scenarios/examples/every-element.yaml scenarios/joints/ragdoll-stairs-60hz.yaml \
  scenarios/closed-form/damped-spring.yaml scenarios/elements/particle-fountain.yaml \
  scenarios/fast-bodies/fast-spinning-rod.yaml scenarios/elements/sensor-gate.yaml
CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$CHROMIUM" ]; then
  echo "check-designer: installing Debian's chromium (once)" >&2
  if [ "$(id -u)" = 0 ]; then SUDO=(); else SUDO=(sudo); fi
  "${SUDO[@]}" apt-get install -y chromium >/dev/null 2>&1 || { "${SUDO[@]}" apt-get update >/dev/null && "${SUDO[@]}" apt-get install -y chromium >/dev/null; }
fi
url="file://$(pwd)/$page/index.html"
# Real time (not --virtual-time-budget), so the page's timing measures: Chromium driven over a pipe.
result=$(timeout 300 python3 designer/src/test/browser/run-page.py "$CHROMIUM" "$url#selftest" 240 "$shots/designer-selftest.png") || true
if [ -z "$result" ]; then
  echo "check-designer: the page's self-test did not report (script error, or no WebAssembly GC in this Chromium)" >&2
  exit 1
fi
printf '%s\n' "$result" > "$check/selftest-result.json"
# The summary without the saved file's bytes.
printf '%s' "$result" | python3 -c 'import json, sys; r = json.load(sys.stdin); r.pop("savedPhy", None); r.pop("sceneYaml", None); print(json.dumps(r))' | cut -c1-4000
echo
size=$(cat "$page"/index.html "$page"/designer.css "$page"/designer.js "$page"/selftest.js "$page"/classes.wasm-runtime.js "$page"/engine-wasm.js | wc -c)
echo "check-designer: page size $size bytes (the engine's module, designer/target/teavm/engine.wasm: $(wc -c < designer/target/teavm/engine.wasm) bytes, embedded as base64)"
# The page's saved world file, read on the JVM by the engine's PhyReader (harness convert).
saved=$(printf '%s' "$result" | sed -n 's/.*"savedPhy":"\([^"]*\)".*/\1/p')
if [ -n "$saved" ]; then
  printf '%s' "$saved" | base64 -d > "$check/page-saved.phy"
  java -cp "$cp" org.emini.harness.cli.Main convert -o "$check/page-saved.yaml" "$check/page-saved.phy" >/dev/null \
    || { echo "check-designer: FAILED: the JVM does not read the page's saved .phy" >&2; exit 1; }
  echo "check-designer: the page's saved .phy ($(wc -c < "$check/page-saved.phy") bytes) reads on the JVM: $check/page-saved.yaml"
  # The page's own scene file (the harness's converter compiled into the page) is what harness convert
  # writes on the JVM (but for the tick rate and iterations the page adds), and a valid scene.
  printf '%s' "$result" | python3 -c 'import json, sys; sys.stdout.write(json.load(sys.stdin)["sceneYaml"])' > "$check/page-scene.yaml"
  if ! grep -q '^  ticksPerSecond: 60$' "$check/page-scene.yaml" \
     || ! grep -v '^  ticksPerSecond: 60$\|^  iterations: 8$' "$check/page-scene.yaml" | cmp -s - "$check/page-saved.yaml"; then
    diff "$check/page-scene.yaml" "$check/page-saved.yaml" | head -n 20 >&2
    echo "check-designer: FAILED: the page's scene file differs from harness convert's" >&2; exit 1
  fi
  java -cp "$cp" org.emini.harness.cli.Main validate "$check/page-scene.yaml" >/dev/null \
    || { echo "check-designer: FAILED: the page's scene file is not a valid scene" >&2; exit 1; }
  echo "check-designer: the page's Save scene .yaml is harness convert's with the page's tick rate, and valid ($(wc -l < "$check/page-scene.yaml") lines)"
fi
# A scene file opened as ./emini designer SCENE opens it (the harness's loader, then the page).
java -cp "$cp" org.emini.designer.SceneExport scenarios/joints/ragdoll-stairs-60hz.yaml "$page/open-check.js" >/dev/null
opened=$(timeout 120 python3 designer/src/test/browser/run-page.py "$CHROMIUM" "$url#open=open-check.js&report" 60 "$shots/designer-scene.png") || true
echo "check-designer: scene opened: $opened"
case "$opened" in *'"ok":true'*) ;; *) echo "check-designer: FAILED: the page did not open the exported scene" >&2; exit 1 ;; esac
# A trace that ./emini run writes, chosen with the page's Open button (over the scene it belongs to).
trace=harness/target/dashboard-smoke/traces/closed-form/projectile-20hz.trace.json
if [ -f "$trace" ]; then
  java -cp "$cp" org.emini.designer.SceneExport scenarios/closed-form/projectile-20hz.yaml "$page/open-trace-check.js" >/dev/null
  traced=$(EMINI_FILE_INPUT="$trace" EMINI_FILE_READY="doc && doc.bodies.length && doc.bodies[0].userData" \
    EMINI_FILE_THEN="reportReplay()" timeout 120 python3 designer/src/test/browser/run-page.py "$CHROMIUM" \
    "$url#open=open-trace-check.js" 60 "$shots/designer-trace.png") || true
  echo "check-designer: trace opened: $traced"
  case "$traced" in *'"ok":true'*) ;; *) echo "check-designer: FAILED: the page did not replay $trace" >&2; exit 1 ;; esac
fi
# The dashboard's replay linked into the page (when ./emini test has written the smoke dashboard).
replay=$(ls harness/target/dashboard-smoke/dashboard/replay/r*.js 2>/dev/null | head -n 1 || true)
if [ -n "$replay" ]; then
  scene=$(sed -n 's/.*window.EMINI_REPLAY\["\([^"]*\)"\].*/\1/p' "$replay" | head -n 1)
  replayed=$(timeout 120 python3 designer/src/test/browser/run-page.py "$CHROMIUM" \
    "$url#replay=$(python3 -c 'import sys, urllib.parse; print(urllib.parse.quote(sys.argv[1], safe=""))' "file://$(pwd)/$replay")&scene=$scene&report" \
    60 "$shots/designer-replay.png") || true
  echo "check-designer: dashboard replay: $replayed"
  case "$replayed" in *'"ok":true'*) ;; *) echo "check-designer: FAILED: the page did not replay $replay" >&2; exit 1 ;; esac
fi
case "$result" in
  *'"ok":true'*) echo "check-designer: ok" ;;
  *) echo "check-designer: FAILED" >&2; exit 1 ;;
esac
