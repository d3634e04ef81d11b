#!/usr/bin/env bash
# How CRT's BVH build and render times grow with the number of objects: renders a scene whose
# size is n = t (set with --time), by default bench/scenes/spheres.crt (n random small spheres),
# for each n and records compile, BVH build and render time and Mrays/s from `crt render --stats`.
#
#   bench/scaling.sh [--runs N] [--sizes "1000 10000 ..."] [--width W --height H] [--out DIR]
#                    [--scene FILE.crt] [--name NAME] [--crt LAUNCHER]
#
# Defaults: 3 runs of each n in 1000 3000 10000 30000 100000 300000 1000000, at 640x360.
# Results: a table of medians on stdout, every run in DIR/NAME-runs.csv and the medians in
# DIR/NAME.csv (default DIR: bench/results, NAME: scaling). --crt runs another build of CRT
# (another checkout's ./crt), to compare versions on the same machine.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
runs=3
sizes="1000 3000 10000 30000 100000 300000 1000000"
width=640
height=360
out="$here/results"
scene="$here/scenes/spheres.crt"
name=scaling
crt="$root/crt"

usage() { sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --sizes) sizes="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --height) height="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --scene) scene="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    --name) name="$2"; shift 2 ;;
    --crt) crt="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "scaling: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

[ -f "$scene" ] || { echo "scaling: no scene file '$scene'" >&2; exit 2; }
"$crt" --version >/dev/null   # build before timing anything
mkdir -p "$out"
out="$(cd "$out" && pwd)"
runs_csv="$out/$name-runs.csv"
csv="$out/$name.csv"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

# Reads the --stats table: prints "compile build render total_rays mrays".
stats() {
  awk '
    /^rays/ { section = "rays" }
    /^time/ { section = "time" }
    section == "rays" && $1 == "total" { gsub(",", "", $2); rays = $2 }
    $1 == "speed" { mrays = $2 }
    section == "time" && $1 == "compile" { compile = $2 }
    section == "time" && $1 == "bvh" { build = $3 }
    section == "time" && $1 == "render" { render = $2 }
    END { print compile, build, render, rays, mrays }' "$1"
}

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores; load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "scene:   ${scene#"$root"/} at ${width}x${height}, median of $runs runs"
echo "n,run,compile_s,build_s,render_s,total_rays,mrays_per_s,wall_s" >"$runs_csv"
echo "n,compile_s,build_s,render_s,mrays_per_s,wall_s" >"$csv"
printf '%9s %10s %10s %10s %10s %10s\n' n "compile s" "build s" "render s" "Mrays/s" "wall s"
for n in $sizes; do
  cs=(); bs=(); rs=(); ms=(); ws=()
  for ((i = 1; i <= runs; i++)); do
    t0="$(date +%s.%N)"
    if ! "$crt" render "$scene" --time "$n" --time-budget 600 \
        --width "$width" --height "$height" --stats -o "$out/$name-$n.png" >"$log" 2>&1; then
      echo "scaling: crt render failed for n = $n:" >&2
      tail -20 "$log" >&2
      exit 1
    fi
    t1="$(date +%s.%N)"
    wall="$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}')"
    read -r c b r rays m <<<"$(stats "$log")"
    echo "$n,$i,$c,$b,$r,$rays,$m,$wall" >>"$runs_csv"
    cs+=("$c"); bs+=("$b"); rs+=("$r"); ms+=("$m"); ws+=("$wall")
  done
  row=("$n" "$(median "${cs[@]}")" "$(median "${bs[@]}")" "$(median "${rs[@]}")" "$(median "${ms[@]}")" "$(median "${ws[@]}")")
  printf '%9s %10s %10s %10s %10s %10s\n' "${row[@]}"
  (IFS=,; echo "${row[*]}") >>"$csv"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "wrote $csv and $runs_csv"
