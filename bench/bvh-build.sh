#!/usr/bin/env bash
# BVH build time and memory from 1e5 to 1e7 items (issue 10 goal 3, issue 12's mesh goal).
#
#   bench/bvh-build.sh [--sizes "100000 1000000 10000000"] [--rounds N] [--heap 2g]
#                      [--scenes | --spheres-scene] [--work DIR] [--jar JAR]
#
# For each size: BvhBuilder.build alone over random spheres (bench/scenes/spheres.crt's
# distribution) and over the triangles of a bumpy ball (bench/tools/MeshGen.java's), N rounds in
# one JVM of --heap (default 2g): wall and process CPU seconds (medians), the tree's node count
# and SAH cost, and the heap per item the tree holds and at most used while building (beyond
# the boxes given to it; the sum of the heap pools' peaks).
# With --scenes, also whole runs as the command line does them, each in a fresh JVM: compile
# bench/scenes/spheres.crt at 1e6 spheres and prepare its geometry (heap held per sphere after
# both), and load a generated 10-million-triangle ball (binary PLY, kept in --work, default
# ${TMPDIR:-/tmp}/crt-bvh-build) and build its BVH, in --heap. --spheres-scene: the first of
# them only (bench/speed-goals.sh reads goal 3's heap per sphere from it; with --sizes "" alone).
# Needs target/crt.jar (mvn -B -q -o package -DskipTests), or the jar given by --jar (another
# build's, to compare side by side: run the two alternately). Numbers move with the machine's
# load: the load average is printed before and after.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
sizes="100000 1000000 10000000"
rounds=3
heap=2g
scenes=0
work="${TMPDIR:-/tmp}/crt-bvh-build"
jar="$root/target/crt.jar"

usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --heap) heap="$2"; shift 2 ;;
    --scenes) scenes=1; shift ;;
    --spheres-scene) scenes=2; shift ;;
    --work) work="$2"; shift 2 ;;
    --jar) jar="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bvh-build: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
if [ ! -f "$jar" ]; then echo "bvh-build: $jar is missing: run mvn -B -q -o package -DskipTests first" >&2; exit 3; fi
classes="$(mktemp -d)"
trap 'rm -rf "$classes"' EXIT
# The tool lives in the renderer's package to reach the builder: compiled here against the jar.
javac -d "$classes" -cp "$jar" "$here/tools/BvhBuild.java"
run() { java "-Xmx$heap" -Xss16m -cp "$classes:$jar" dev.crt.render.BvhBuild "$@"; }

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores, java $(java -version 2>&1 | head -1 | cut -d'"' -f2), -Xmx$heap; load $(cut -d' ' -f1-3 /proc/loadavg) before"
for n in $sizes; do
  for kind in spheres ball; do
    run boxes "$kind" "$n" "$rounds" | tail -1
  done
done
if [ "$scenes" != 0 ]; then
  run scene "$root/bench/scenes/spheres.crt" 1000000 | head -1
fi
if [ "$scenes" = 1 ]; then
  mkdir -p "$work"
  ply="$work/ball-10000000.ply"
  if [ ! -f "$ply" ]; then java "$here/tools/MeshGen.java" 10000000 "$ply" >/dev/null; fi
  cat >"$work/ball-10000000.crt" <<CRT
Scene { Mesh { file -> "ball-10000000.ply" smooth -> false material -> Material { color -> rgb(0.8, 0.5, 0.3) } } }
CRT
  run scene "$work/ball-10000000.crt" 0 | head -1
fi
echo "load $(cut -d' ' -f1-3 /proc/loadavg) after"
