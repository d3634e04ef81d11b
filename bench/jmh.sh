#!/usr/bin/env bash
# JMH micro-benchmarks of the renderer's kernels (src/test/java/dev/crt/render/*Benchmark.java):
# one ray against a sphere or a box, rays through the BVH of 1,000 and 100,000 spheres, rays
# through CSG solids, the BVH build over 100,000 boxes, and a whole 64x48 render on one thread.
#
#   bench/jmh.sh [JMH OPTIONS...] [BENCHMARK REGEX...]
#
# Default: every CRT benchmark with short runs (-f 1 -wi 3 -i 5 -w 1s -r 1s). Options are passed
# to JMH and replace the defaults they name, e.g. `bench/jmh.sh CsgBenchmark`, `bench/jmh.sh -i 10
# BvhTraversal`, `bench/jmh.sh -l` (list), `bench/jmh.sh -h` (this text), `bench/jmh.sh -- -h`
# (JMH's own options). Results: bench/results/jmh.csv and the console output in bench/results/jmh.txt.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
out="$here/results"

usage() { sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
case "${1:-}" in
  -h|--help) usage; exit 0 ;;
  --) shift ;;
esac
command -v mvn >/dev/null || { echo "jmh: needs Maven (apt-get install maven)" >&2; exit 1; }

cd "$root"
# Offline when everything is in the local repository already; the first run fetches JMH.
mvn_q() { mvn -B -q -o -Dstyle.color=never "$@" >/dev/null 2>&1 || mvn -B -q -Dstyle.color=never "$@"; }
mvn_q test-compile
cp_file="$(mktemp)"
trap 'rm -f "$cp_file"' EXIT
mvn_q dependency:build-classpath -Dmdep.includeScope=test -Dmdep.outputFile="$cp_file"
classpath="$root/target/test-classes:$root/target/classes:$(cat "$cp_file")"

# JMH refuses an option given twice: the defaults go in only where the arguments lack them. Its
# options all take a value except a few flags; any other argument is a benchmark regex.
selected=no
given=" "
args=("$@")
for ((k = 0; k < ${#args[@]}; k++)); do
  case "${args[k]}" in
    -h|-l|-lp|-lprof|-lrf) ;;
    -*) given+="${args[k]} "; k=$((k + 1)) ;;
    *) selected=yes ;;
  esac
done
defaults=()
for pair in -f=1 -wi=3 -i=5 -w=1s -r=1s -rf=csv "-rff=$out/jmh.csv"; do
  option="${pair%%=*}"
  [[ "$given" == *" $option "* ]] || defaults+=("$option" "${pair#*=}")
done
[ "$selected" = yes ] || set -- "$@" 'dev\.crt\..*Benchmark'

mkdir -p "$out"
java -cp "$classpath" org.openjdk.jmh.Main "${defaults[@]}" "$@" 2>&1 | tee "$out/jmh.txt"
