#!/usr/bin/env bash
# The studio's speed figures (docs/studio.md): start to a painted window with ./crt studio, then
# keystroke to squiggle on 2,500 lines and F5 to first picture per example scene (StudioBench).
# Runs on a virtual X display of its own (CRT_BENCH_DISPLAY=N picks its number). Needs Xvfb. An
# argument names another folder of scenes for the F5 figures (an empty one measures the editor only).
# Last, the typing figure of issue 7 (no EDT stall over 50 ms while typing): CRT_BENCH_TYPING_RUNS
# studios (5 unless set) each type five keystrokes into 2,500 lines, and the longest stall of each is
# printed on one line, with how many were under 50 ms and the load average (measure on a quiet machine);
# each studio's output, with the EDT's stack during every stall over 50 ms, is kept in target/studio-bench/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
display="${CRT_BENCH_DISPLAY:-}"
for n in $( [ -z "$display" ] && seq 200 249); do
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

# The studio's own start-up cache is made in the background by the first `crt studio`; wait for it.
# The launcher's Java and its cache (the first cache listed could be another Java's, left by a run with CRT_JAVA).
IFS='|' read -r java_bin java_version < <(bash -c 'source <(sed -n "/^java_version()/,/^fi$/p" "$1"); echo "$java|$version"' _ "$here/crt")
if [ "${java_version%%.*}" -ge 25 ] 2>/dev/null; then version_cache="target/crt-$java_version.aot"; else version_cache="target/crt-${java_version:-java}.jsa"; fi
[ -f "$version_cache" ] || version_cache=""
if [ -n "$version_cache" ]; then
  studio_cache="${version_cache%.*}-studio.${version_cache##*.}"
  if [ ! -f "$studio_cache" ] || [ "$studio_cache" -ot target/crt.jar ]; then
    # A stale cache goes first: waiting below for "a cache" would otherwise return at once and
    # time the studio beside its own training run.
    rm -f "$studio_cache"
    XDG_CONFIG_HOME="$work/c0" XDG_STATE_HOME="$work/s0" CRT_JAVA_OPTS="-Xss16m -Dcrt.studio.quitWhenReady=true -Djava.util.prefs.userRoot=$work/p" \
      ./crt studio scenes/dice.crt >/dev/null 2>&1 || true
    for _ in $(seq 1 240); do [ -f "$studio_cache" ] && [ ! -f "$studio_cache.tmp" ] && break; sleep 0.5; done
    [ -f "$studio_cache" ] || echo "the studio's start-up cache was not made (see target/studio-train/train.log)" >&2
  fi
fi

echo "start to a painted window (./crt studio scenes/dice.crt, wall time from the command to the studio's"
echo "'ready' after its first paint), with the studio's start-up cache and without (CRT_STUDIO_CACHE=0), alternating:"
for i in 1 2 3; do
  for cache in 1 0; do
    start=$(date +%s%N)
    line=$(XDG_CONFIG_HOME="$work/c$i$cache" XDG_STATE_HOME="$work/s$i$cache" CRT_STUDIO_CACHE=$cache \
      CRT_JAVA_OPTS="-Xss16m -Dcrt.studio.quitWhenReady=true -Djava.util.prefs.userRoot=$work/p" \
      ./crt studio scenes/dice.crt 2>/dev/null | grep 'studio ready' || echo "no ready line")
    echo "  cache=$cache: $(( ($(date +%s%N) - start) / 1000000 )) ms  ($line)"
  done
done

# The editor and render figures, in the studio as users run it: the jar ./crt runs, its Java, and on
# Java 24 and later the studio's start-up cache (the bench's own classes come after the jar on the class
# path, which the cache allows); the classes a first error notice or the first property sheet need are
# then in the cache, as they are for users.
opts=(-Xss16m)
# and its garbage collector: the launcher's studio options (CRT_STUDIO_GC=g1 keeps G1, as for ./crt studio).
eval "$(grep '^studio_gc=' "$here/crt")"
collector=G1
if [ "${CRT_STUDIO_GC:-}" != g1 ] && "$java_bin" "${studio_gc[@]}" -version >/dev/null 2>&1; then
  opts+=("${studio_gc[@]}")
  collector="${studio_gc[*]}"
fi
if [ -n "$version_cache" ] && [ "${version_cache##*.}" = aot ] && [ -f "$studio_cache" ]; then
  opts+=(-XX:AOTCache="$studio_cache" -Xlog:aot=off -Xlog:cds=off --enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow)
  echo "editor and render figures: $("$java_bin" -version 2>&1 | head -1), collector $collector, with the studio's start-up cache"
elif [ -n "$version_cache" ] && [ -f "$studio_cache" ]; then
  opts+=(-XX:SharedArchiveFile="$studio_cache" -Xshare:auto -Xlog:cds=off)
  echo "editor and render figures: $("$java_bin" -version 2>&1 | head -1), collector $collector, with the studio's class-data archive"
else
  echo "editor and render figures: $("$java_bin" -version 2>&1 | head -1), collector $collector, no start-up cache"
fi
"$java_bin" "${opts[@]}" -Dcrt.assets="$here/assets" -Djava.util.prefs.userRoot="$work/p" \
  -cp "$here/target/crt.jar:$here/target/test-classes" dev.crt.studio.StudioBench "${1:-scenes}"

mkdir -p "$work/none"
runs="${CRT_BENCH_TYPING_RUNS:-5}"
# Each studio's output is kept, with the EDT's stack during every stall over 50 ms: what is left to fix.
logs="$here/target/studio-bench"
mkdir -p "$logs"
rm -f "$logs"/typing-*.log
stalls=() under=0 loads=()
for i in $(seq 1 "$runs"); do
  loads+=("$(cut -d' ' -f1 /proc/loadavg)")
  "$java_bin" "${opts[@]}" -Djava.util.prefs.userRoot="$work/p" -Dcrt.watchdog.printMs=50 -Dcrt.watchdog.frames=30 \
    -cp "$here/target/crt.jar:$here/target/test-classes" dev.crt.studio.StudioBench "$work/none" >"$logs/typing-$i.log" 2>&1 || true
  ms=$(sed -n 's/^TYPING STALL \([0-9]*\) ms.*/\1/p' "$logs/typing-$i.log")
  stalls+=("${ms:-?}")
  [ -n "$ms" ] && [ "$ms" -lt 50 ] && under=$((under + 1))
done
echo "TYPING STALLS (longest EDT stall during five keystrokes into 2,500 lines, $runs studios): ${stalls[*]} ms;" \
  "$under of $runs under 50 ms; collector $collector (its pauses count as stalls); load average at each start: ${loads[*]}"
echo "each studio's output, with the EDT's stack during any stall over 50 ms: $logs/typing-N.log"
