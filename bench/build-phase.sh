#!/usr/bin/env bash
# The "compile" and "bvh build" phases of 1e6 spheres as the user sees them (issue 10 goal 3),
# several builds side by side.
#
#   bench/build-phase.sh [--runs N] [--spheres N] DIR...
#
# Each DIR is a CRT tree with its launcher and its built jar (DIR/crt, DIR/target/crt.jar), for
# instance this checkout and a copy of another build's (cp crt OTHER/; cp target/crt.jar
# OTHER/target/): each launcher makes and uses its own start-up cache. The runs alternate
# between the DIRs, N rounds (default 5), each a fresh process of
#   DIR/crt render bench/scenes/spheres.crt --time N --time-budget 600 --width 16 --height 16 --stats
# printing the two phases as --stats prints them and the process's CPU (user + system, from
# /usr/bin/time), then the medians per DIR. Numbers move with the machine's load: the load
# average is printed with every run.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
runs=5
spheres=1000000
dirs=()
usage() { sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --spheres) spheres="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "build-phase: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    *) dirs+=("$(cd "$1" && pwd)"); shift ;;
  esac
done
if [ ${#dirs[@]} -eq 0 ]; then usage >&2; exit 2; fi
for d in "${dirs[@]}"; do
  if [ ! -x "$d/crt" ] || [ ! -f "$d/target/crt.jar" ]; then echo "build-phase: $d has no crt launcher or target/crt.jar" >&2; exit 3; fi
  # A first run makes the launcher's start-up cache, so that the measured runs all use one.
  "$d/crt" --version >/dev/null
done
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "load $(cut -d' ' -f1-3 /proc/loadavg) before"
for ((i = 0; i < runs; i++)); do
  for k in "${!dirs[@]}"; do
    d="${dirs[$k]}"
    log=$({ /usr/bin/time -f "cpu %U %S" "$d/crt" render "$here/scenes/spheres.crt" --time "$spheres" --time-budget 600 \
      --width 16 --height 16 --stats -o "$out/x.png"; } 2>&1)
    compile=$(awk '$1 == "compile" {print $2}' <<<"$log")
    build=$(awk '$1 == "bvh" && $2 == "build" {print $3}' <<<"$log")
    cpu=$(awk '$1 == "cpu" {printf "%.2f", $2 + $3}' <<<"$log")
    echo "$compile $build $cpu" >>"$out/$k"
    printf '%s: compile %s s, bvh build %s s, process CPU %s s (load %s)\n' "$d" "$compile" "$build" "$cpu" "$(cut -d' ' -f1 /proc/loadavg)"
  done
done
median() { sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
for k in "${!dirs[@]}"; do
  printf '%s: medians of %d: compile %s s, bvh build %s s, process CPU %s s\n' "${dirs[$k]}" "$runs" \
    "$(cut -d' ' -f1 "$out/$k" | median)" "$(cut -d' ' -f2 "$out/$k" | median)" "$(cut -d' ' -f3 "$out/$k" | median)"
done
echo "load $(cut -d' ' -f1-3 /proc/loadavg) after"
