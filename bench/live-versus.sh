#!/usr/bin/env bash
# The live view against another revision, side by side (docs/benchmarks.md, "Live view, second
# round"): the revision's main classes are built in target/versus/REV, and this tree's benchmark
# programs (dev.crt.live.LiveLatency, dev.crt.live.LiveBenchmark) run on both, alternating, so
# both see the same load. Usage: bench/live-versus.sh [REV] [ROUNDS]   (default: main, 2 rounds)
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-main}
rounds=${2:-2}
sha=$(git rev-parse --short "$rev")
other=target/versus/$sha
mvn -B -q -o test-compile
mvn -B -q -o dependency:build-classpath -Dmdep.outputFile=target/classpath.txt >/dev/null
if [ ! -d "$other/target/classes" ]; then
  rm -rf "$other" && mkdir -p "$other"
  git archive "$sha" | tar -x -C "$other"
  mvn -B -q -o -f "$other/pom.xml" compile
fi
deps=$(cat target/classpath.txt)
scenes=(src/test/resources/dev/crt/studio/two-spheres.crt scenes/dice.crt scenes/csg-sculpture.crt scenes/still-life.crt)
for round in $(seq "$rounds"); do
  for side in "$sha:$other/target/classes" "this tree:target/classes"; do
    name=${side%%:*}
    classes=${side#*:}
    echo "== round $round, $name; $(uptime)"
    java -cp "$classes:target/test-classes:$deps" dev.crt.live.LiveLatency "${scenes[@]}"
    java -cp "$classes:target/test-classes:$deps" dev.crt.live.LiveBenchmark
  done
done
