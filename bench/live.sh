#!/usr/bin/env bash
# The live view's speed figures (docs/benchmarks.md, section "Live view"): frames/s while
# orbiting 1,000 objects at 800x600, the converter on 10,000 objects, and crt preview as a whole
# process. Usage: bench/live.sh   (prints to stdout; results also in bench/results/live.txt)
set -euo pipefail
cd "$(dirname "$0")/.."
mvn -B -q -o test-compile
mvn -B -q -o dependency:build-classpath -Dmdep.outputFile=target/classpath.txt >/dev/null
cp="target/classes:target/test-classes:$(cat target/classpath.txt)"
mkdir -p bench/results
{
  java -cp "$cp" dev.crt.live.LiveBenchmark
  ./crt check scenes/csg-sculpture.crt >/dev/null   # builds target/crt.jar first if needed
  for i in 1 2 3; do
    /usr/bin/time -f "crt preview scenes/csg-sculpture.crt (960x540), whole process, run $i: %e s wall clock, %U s user + %S s system CPU" \
      ./crt preview scenes/csg-sculpture.crt -o target/preview-bench.png -q
  done 2>&1
} | tee bench/results/live.txt
