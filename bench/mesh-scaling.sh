#!/usr/bin/env bash
# Meshes from 1e3 to 1e7 triangles: how CRT's load, BVH build and render grow with the triangle
# count, and the same scene against POV-Ray's mesh2, whole process, side by side.
#
#   bench/mesh-scaling.sh [--sizes "1000 10000 100000 1000000"] [--runs N] [--width W --height H]
#                         [--work DIR] [--out DIR] [--no-povray]
#
# The mesh is a closed bumpy ball (bench/tools/MeshGen.java: binary PLY for CRT, the same float
# vertices and faces as a mesh2 include for POV-Ray), flat-shaded, one point light with shadows,
# 1 sample per pixel, every core. Generated meshes are kept in the work folder (default
# bench/results/meshes; 1e7 triangles take 190 MB of PLY and 420 MB of mesh2).
# Results: a table on stdout and DIR/mesh-scaling.csv (default DIR: bench/results) with, per size
# and run, CRT's whole-process wall and CPU seconds, its compile (file read), BVH build and render
# phases from --stats, and POV-Ray's wall and CPU seconds with its parse and trace times.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
sizes="1000 10000 100000 1000000"
runs=3
width=1280
height=720
work="$here/results/meshes"
out="$here/results"
povray=1

usage() { sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --height) height="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --no-povray) povray=0; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "mesh-scaling: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
if [ ! -x /usr/bin/time ]; then echo "mesh-scaling: GNU time is needed (/usr/bin/time): sudo apt-get install time" >&2; exit 3; fi
if [ "$povray" = 1 ] && ! command -v povray >/dev/null 2>&1; then
  echo "mesh-scaling: POV-Ray is not installed (sudo apt-get install povray), or pass --no-povray" >&2
  exit 3
fi
"$root/crt" --version >/dev/null
mkdir -p "$work" "$out"
work="$(cd "$work" && pwd)"
out="$(cd "$out" && pwd)"
csv="$out/mesh-scaling.csv"
cores="$(nproc)"
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT

timed() {
  local log="$1"; shift
  local tf
  tf="$(mktemp)"
  if ! /usr/bin/time -o "$tf" -f '%e %U %S' "$@" >"$log" 2>&1; then
    echo "mesh-scaling: command failed: $*" >&2
    tail -20 "$log" >&2
    rm -f "$tf"
    exit 1
  fi
  awk '{printf "%.2f %.2f", $1, $2 + $3}' "$tf"
  rm -f "$tf"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
phase() { awk -v k="$2" '$1 == k && $NF == "s" {print $(NF-1)}' "$1" | tail -1; }

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $cores cores; load $(cut -d' ' -f1-3 /proc/loadavg) before"
echo "scene:   a closed bumpy ball mesh, ${width}x${height}, 1 sample per pixel, one point light with shadows"
echo "size,run,crt_wall_s,crt_cpu_s,crt_compile_s,crt_bvh_s,crt_render_s,pov_wall_s,pov_cpu_s,pov_parse_s,pov_trace_s" >"$csv"
printf '%-9s %-4s %9s %8s %8s %8s %8s | %9s %8s %8s %8s\n' triangles run "CRT wall" "cpu" "compile" "bvh" "render" "POV wall" "cpu" "parse" "trace"
for n in $sizes; do
  ply="$work/ball-$n.ply"
  inc="$work/ball-$n.inc"
  if [ ! -f "$ply" ] || { [ "$povray" = 1 ] && [ ! -f "$inc" ]; }; then
    java "$here/tools/MeshGen.java" "$n" "$ply" "$inc" >/dev/null
  fi
  cat >"$work/ball-$n.crt" <<CRT
Settings {
  camera -> Camera { position -> vec3(0, 0.6, -3.2) pointing -> vec3(0, 0, 0) fov -> 45 }
  lights -> [ PointLight { origin -> vec3(-4, 5, -6) color -> rgb(0.9, 0.9, 0.9) } ]
  background -> Background { horizon -> rgb(0.85, 0.88, 0.95) sky -> rgb(0.85, 0.88, 0.95) }
}
Scene { Mesh { file -> "ball-$n.ply" smooth -> false material -> Material { color -> rgb(0.8, 0.5, 0.3) diffuse -> 0.8 specular -> 0.4 shininess -> 40 } } }
CRT
  cat >"$work/ball-$n.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 1 ambient_light rgb 0 }
camera { perspective location <0, 0.6, -3.2> right x * $width / $height up y
  angle 2 * degrees(atan(tan(radians(45 / 2)) * $width / $height)) look_at <0, 0, 0> }
light_source { <-4, 5, -6> color rgb <0.9, 0.9, 0.9> }
background { color rgb <0.85, 0.88, 0.95> }
#include "ball-$n.inc"
  texture { pigment { color rgb <0.8, 0.5, 0.3> } finish { ambient 0 diffuse 0.8 specular 0.4 roughness 1 / 40 } } }
POV
  crt_cmd=("$root/crt" render "$work/ball-$n.crt" -o "$work/ball-$n-crt.png" --width "$width" --height "$height" --stats)
  pov_cmd=(povray -D -A "+WT$cores" "+W$width" "+H$height" +FN File_Gamma=1.0 "+I$work/ball-$n.pov" "+O$work/ball-$n-povray.png")
  walls=(); cpus=(); pwalls=(); pcpus=()
  for ((i = 1; i <= runs; i++)); do
    read -r c ccpu <<<"$(timed "$logs/crt.log" "${crt_cmd[@]}")"
    comp="$(phase "$logs/crt.log" compile)"; bvh="$(phase "$logs/crt.log" bvh)"; rend="$(phase "$logs/crt.log" render)"
    p="-"; pcpu="-"; parse="-"; trace="-"
    if [ "$povray" = 1 ]; then
      read -r p pcpu <<<"$(cd "$work" && timed "$logs/pov.log" "${pov_cmd[@]}")"
      parse="$(grep -m1 'Parse Time' "$logs/pov.log" | sed 's/.*(\([0-9.]*\) seconds).*/\1/' || true)"
      trace="$(grep -m1 'Trace Time' "$logs/pov.log" | sed 's/.*(\([0-9.]*\) seconds).*/\1/' || true)"
      pwalls+=("$p"); pcpus+=("$pcpu")
    fi
    walls+=("$c"); cpus+=("$ccpu")
    printf '%-9s %-4s %9s %8s %8s %8s %8s | %9s %8s %8s %8s\n' "$n" "$i" "$c" "$ccpu" "$comp" "$bvh" "$rend" "$p" "$pcpu" "$parse" "$trace"
    echo "$n,$i,$c,$ccpu,$comp,$bvh,$rend,$p,$pcpu,$parse,$trace" >>"$csv"
  done
  if [ "$povray" = 1 ]; then
    echo "  $n triangles, medians: CRT wall $(median "${walls[@]}") s, POV-Ray $(median "${pwalls[@]}") s, ratio $(awk -v c="$(median "${walls[@]}")" -v p="$(median "${pwalls[@]}")" 'BEGIN {printf "%.2f", c / p}'); CPU ratio $(awk -v c="$(median "${cpus[@]}")" -v p="$(median "${pcpus[@]}")" 'BEGIN {printf "%.2f", c / p}')"
  fi
done
echo "load $(cut -d' ' -f1-3 /proc/loadavg) after; CSV: $csv"
