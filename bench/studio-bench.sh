#!/usr/bin/env bash
# The studio's speed figures (docs/studio.md): start to window with ./crt studio, then
# keystroke to squiggle on 2,500 lines and F5 to first picture per example scene (StudioBench).
# Runs on a virtual X display of its own. Needs Xvfb and xdotool.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
display=""
for n in $(seq 200 249); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=$n; break; fi
done
work="$(mktemp -d)"
Xvfb ":$display" -screen 0 1600x1000x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
export DISPLAY=":$display"
sleep 1
mvn -B -q -o -DskipTests package test-compile >/dev/null
./crt --version >/dev/null   # builds the class-data archive if needed

echo "start to window (./crt studio scenes/dice.crt until the window is mapped), 3 runs:"
for i in 1 2 3; do
  start=$(date +%s%N)
  XDG_CONFIG_HOME="$work/c$i" XDG_STATE_HOME="$work/s$i" CRT_JAVA_OPTS="-Xss16m -Djava.util.prefs.userRoot=$work/p" \
    ./crt studio scenes/dice.crt >/dev/null 2>&1 &
  pid=$!
  xdotool search --sync --onlyvisible --name "CRT Studio" >/dev/null
  echo "  $(( ($(date +%s%N) - start) / 1000000 )) ms"
  kill $pid; wait $pid 2>/dev/null || true
done

mvn -B -q -o dependency:build-classpath -Dmdep.outputFile="$work/cp.txt" >/dev/null
cp=$(cat "$work/cp.txt")
java -Xss16m -Dcrt.assets="$here/assets" -Djava.util.prefs.userRoot="$work/p" -cp "target/test-classes:target/classes:$cp" dev.crt.studio.StudioBench scenes
