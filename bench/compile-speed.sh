#!/usr/bin/env bash
# Compile speed on a written-out script, the way exporters write scenes: N spheres (default
# 10,000), each with its own Material { … } block, no loops. Prints the script's size, the compile
# phase of `crt render --stats` (median of the runs) and megabytes per second, against the goal
# of issue 10 (at least 10 MB/s). With --busy, another JVM keeps one core busy meanwhile
# (bench/tools/BusyCore.java), as on a shared machine.
#
#   bench/compile-speed.sh [--spheres N] [--runs N] [--busy]
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
n=10000
runs=3
busy=0
usage() { sed -n '2,8p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --spheres) n="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --busy) busy=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compile-speed: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

"$root/crt" --version >/dev/null # build outside the timing
work="$(mktemp -d)"
busy_pid=""
trap '[ -z "$busy_pid" ] || kill "$busy_pid" 2>/dev/null; rm -rf "$work"' EXIT
script="$work/written.crt"
# A fixed linear congruential generator, so every run and machine compiles the same text.
awk -v n="$n" 'BEGIN {
  s = 12345
  print "Settings {"
  print "  camera -> Camera { position -> vec3(0, 0, -32) pointing -> vec3(0, 0, 0) fov -> 40 }"
  print "  lights -> [ PointLight { origin -> vec3(-30, 40, -50) color -> rgb(0.8, 0.8, 0.8) ambient -> 0.2 } ]"
  print "  recursiondepth -> 0"
  print "}"
  print "Scene {"
  r = 16 / sqrt(n)
  for (i = 0; i < n; i++) {
    for (k = 0; k < 6; k++) { s = (s * 1103515245 + 12345) % 2147483648; u[k] = s / 2147483648 }
    printf "  Sphere {\n    center -> vec3(%.6f, %.6f, %.6f)\n    radius -> %.6f\n", 20 * u[0] - 10, 20 * u[1] - 10, 20 * u[2] - 10, r
    printf "    material -> Material {\n      color -> rgb(%.4f, %.4f, %.4f)\n      diffuse -> 0.8\n      specular -> 0.4\n      shininess -> 30\n    }\n  }\n", u[3], u[4], u[5]
  }
  print "}"
}' >"$script"
bytes="$(wc -c <"$script")"
if [ "$busy" = 1 ]; then
  java="${CRT_JAVA:-java}"
  "$java" "$here/tools/BusyCore.java" $((10 + 3 * runs)) >/dev/null 2>&1 &
  busy_pid=$!
  sleep 3 # its compile and warm-up
fi
times=()
for ((i = 1; i <= runs; i++)); do
  "$root/crt" render "$script" -o "$work/w.png" --width 16 --height 16 --stats >"$work/log" 2>&1
  c="$(awk '$1 == "compile" {print $2}' "$work/log")"
  times+=("$c")
  echo "run $i: compile $c s"
done
med="$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}')"
echo "script: $n spheres each with its own material, $bytes bytes"
echo "java:   $("$root/crt" --version | sed -n 2p)"
echo "load:   $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min)$([ "$busy" = 1 ] && echo ", one core kept busy by another JVM")"
echo "compile (median of $runs): $med s, $(awk -v b="$bytes" -v t="$med" 'BEGIN {printf "%.2f", b / 1e6 / t}') MB/s (goal: at least 10 MB/s)"
