#!/usr/bin/env bash
# The live view's compile-to-frame time by phase (docs/live-view.md, "Following the compiles"):
# compile, convert, upload, draw, read back, into the panel's image, headless, at 800x600.
# Usage: bench/live-latency.sh [SCENE...]   (default: three example scenes)
set -euo pipefail
cd "$(dirname "$0")/.."
mvn -B -q -o test-compile
mvn -B -q -o dependency:build-classpath -Dmdep.outputFile=target/classpath.txt >/dev/null
cp="target/classes:target/test-classes:$(cat target/classpath.txt)"
if [ $# -eq 0 ]; then set -- src/test/resources/dev/crt/studio/two-spheres.crt scenes/dice.crt scenes/csg-sculpture.crt; fi
uptime
java -cp "$cp" dev.crt.live.LiveLatency "$@"
