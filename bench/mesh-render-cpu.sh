#!/usr/bin/env bash
# Render time against triangle count, 1e3 to 1e7: the CPU seconds of one render thread in a warm
# JVM (bench/tools/RenderCpu.java: compile, prepare, then RENDERS renders and their median), so
# that the figures hold on a busy machine where wall-clock times do not.
#
#   bench/mesh-render-cpu.sh [--sizes "1000 10000 100000 1000000 10000000"] [--renders N]
#                            [--width W --height H] [--work DIR] [--out DIR]
#
# The scene is bench/mesh-scaling.sh's: a closed bumpy ball of about n triangles
# (bench/tools/MeshGen.java, binary PLY), flat-shaded, one point light with shadows, 1 sample per
# pixel. Meshes are kept in the work folder (default bench/results/meshes, shared with
# mesh-scaling.sh). Results: a table on stdout and DIR/mesh-render-cpu.csv (default DIR:
# bench/results) with the triangle count, the compile, prepare (BVH builds) and median render CPU
# seconds; bench/charts.sh draws docs/images/bench-mesh-render.png from it.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
sizes="1000 10000 100000 1000000 10000000"
renders=3
width=1280
height=720
work="$here/results/meshes"
out="$here/results"

usage() { sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --renders) renders="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --height) height="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "mesh-render-cpu: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

"$root/crt" --version >/dev/null
jar="$root/target/crt.jar"
mkdir -p "$work" "$out"
work="$(cd "$work" && pwd)"
csv="$out/mesh-render-cpu.csv"
tmp="$csv.tmp"
echo "triangles,compile_cpu_s,prepare_cpu_s,render_cpu_s" >"$tmp"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) before the runs"
printf '%-10s %12s %12s %12s\n' triangles "compile s" "prepare s" "render s"
for n in $sizes; do
  ply="$work/ball-$n.ply"
  [ -f "$ply" ] || java "$here/tools/MeshGen.java" "$n" "$ply" >/dev/null
  scene="$work/ball-$n-cpu.crt"
  cat >"$scene" <<CRT
Settings {
  camera -> Camera { position -> vec3(0, 0.6, -3.2) pointing -> vec3(0, 0, 0) fov -> 45 }
  lights -> [ PointLight { origin -> vec3(-4, 5, -6) color -> rgb(0.9, 0.9, 0.9) } ]
  background -> Background { horizon -> rgb(0.85, 0.88, 0.95) sky -> rgb(0.85, 0.88, 0.95) }
}
Scene { Mesh { file -> "ball-$n.ply" smooth -> false material -> Material { color -> rgb(0.8, 0.5, 0.3) diffuse -> 0.8 specular -> 0.4 shininess -> 40 } } }
CRT
  # The PLY header holds the face count: the triangle count of the table.
  faces="$(head -c 400 "$ply" | tr -d '\r' | awk '$1 == "element" && $2 == "face" {print $3; exit}')"
  line="$(java -Xss16m -Xmx6g -cp "$jar" "$here/tools/RenderCpu.java" "$scene" "$width" "$height" "$renders")"
  # "compile C prepare P renders … median M"
  c="$(awk '{print $2}' <<<"$line")"
  p="$(awk '{print $4}' <<<"$line")"
  m="$(awk '{print $NF}' <<<"$line")"
  printf '%-10s %12s %12s %12s\n' "${faces:-$n}" "$c" "$p" "$m"
  echo "${faces:-$n},$c,$p,$m" >>"$tmp"
done
mv -f "$tmp" "$csv"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the runs"
echo "results: $csv"
