#!/usr/bin/env bash
# A fresh Maven project outside the repository that depends only on the engine artifact compiles and
# runs the README's first example (issue 21). The engine (jar and its standalone, flattened POM, as
# `mvn install` and Central would hold them) goes into a private local repository, .m2-consumer/, so
# that SNAPSHOTs other checkouts install in ~/.m2 play no part. The first run downloads the two
# plugins the consumer uses into it; later runs are offline.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
repo="${EMINI_CONSUMER_REPO:-$root/.m2-consumer}"
version="$(sed -n 's|^  <version>\(.*\)</version>|\1|p' "$root/engine/.flattened-pom.xml" | head -n 1)"
jar="$root/engine/target/emini-engine-$version.jar"
[ -f "$jar" ] || { echo "consumer: $jar is missing: build the engine first (mvn install)" >&2; exit 1; }
if grep -q '<parent>' "$root/engine/.flattened-pom.xml"; then
  echo "consumer: the engine's published POM names a parent that is not published" >&2; exit 1
fi
dir="$repo/org/emini/emini-engine/$version"
rm -rf "$repo/org/emini"
mkdir -p "$dir"
cp "$jar" "$dir/emini-engine-$version.jar"
cp "$root/engine/.flattened-pom.xml" "$dir/emini-engine-$version.pom"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp -r "$root/examples/consumer/pom.xml" "$root/examples/consumer/src" "$work/"
mvn_consumer() {
  mvn -B -q -f "$work/pom.xml" -Dmaven.repo.local="$repo" -Demini.version="$version" "$@" compile
}
mvn_consumer -o > "$work/build.log" 2>&1 || mvn_consumer > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
out="$(java -cp "$work/target/classes:$dir/emini-engine-$version.jar" org.example.Main)"
echo "consumer (outside the repository, engine $version from its artifact only): $out"
# The box falls onto the ground within the 3 s and rests on it: its centre 20 px above the ground's
# (y = -10, less the solver's slop), near x = 0.
echo "$out" | awk -F'[, ]+' '{ if ($1 < -1 || $1 > 1 || $2 < -10.1 || $2 > -9.9) exit 1 }' \
  || { echo "consumer: the box is not resting on the ground: $out" >&2; exit 1; }
