#!/usr/bin/env bash
# Renders one scene with an earlier build of CRT (a jar) and with this one (./crt), alternating,
# and prints the ratios of the medians (this / earlier; below 1.0 means this build is faster) of
# the whole-process user + system CPU time and wall-clock time, and how far the pictures differ.
#
#   bench/jar-compare.sh --base OLD.jar [--runs N] [--out DIR] [--same-java] [--new-arg X]... SCENE.crt [crt render options...]
#
# The earlier build runs as `java -jar OLD.jar` with the java on the PATH (as its launcher did),
# this one through ./crt (the newest Java it finds, with its start-up cache); --same-java runs the
# earlier build with the same java as ./crt instead, which separates the code's gain from the JDK's.
# Options after the scene go to both renders (--width, --height, --assets, --threads …).
# CPU time is the figure to trust on a shared machine: others' work slows wall-clock time more.
# Goal 1 of issue 10 (drops.crt of CRT 2015 at its shipped settings in ≤ 0.4× f05acbf's time):
#   bench/jar-compare.sh --base f05acbf.jar --new-arg --sampler --new-arg grid DATA/drops.crt --assets DATA/assets
# (--new-arg X passes X to this build only: here f05acbf's sampling, since from 2 Dec 2026 a scene
# with depth of field that names no sampler gets Sobol, a different picture of the same budget)
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
runs=3
out="$here/results"
base=""
same=0
new_only=()
usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --base) base="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --same-java) same=1; shift ;;
    --new-arg) new_only+=("$2"); shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "jar-compare: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { echo "jar-compare: the scene is missing" >&2; usage >&2; exit 2; }
[ -f "$base" ] || { echo "jar-compare: --base names no jar: '$base'" >&2; exit 2; }
scene="$1"
shift
[ -f "$scene" ] || { echo "jar-compare: no such scene: $scene" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "jar-compare: GNU time is needed (/usr/bin/time): sudo apt-get install time" >&2; exit 3; }

"$root/crt" --version >/dev/null # builds target/crt.jar and its start-up cache outside the timing
new_java="$("$root/crt" --version | sed -n 2p)"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
name="$(basename "$scene" .crt)"
base_java=java
if [ "$same" = 1 ]; then
  # The java ./crt runs: the launcher prints its version; find that JDK the way the launcher does.
  base_java="$(bash -c 'source <(sed -n "/^java_version()/,/^fi$/p" "$1"); echo "$java"' _ "$root/crt")"
fi
new_cmd=("$root/crt" render "$scene" -o "$out/$name-new.png" --stats "$@" ${new_only[@]+"${new_only[@]}"})
base_cmd=("$base_java" -Xss16m -jar "$base" render "$scene" -o "$out/$name-base.png" --stats "$@")

timed() { # runs a command; prints wall and user+system CPU seconds
  local log="$1"; shift
  local tf
  tf="$(mktemp)"
  if ! /usr/bin/time -o "$tf" -f '%e %U %S' "$@" >"$log" 2>&1; then
    echo "jar-compare: command failed: $*" >&2
    tail -20 "$log" >&2
    exit 1
  fi
  awk '{printf "%.2f %.2f", $1, $2 + $3}' "$tf"
  rm -f "$tf"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) before the runs"
echo "base:    ${base_cmd[*]} ($("$base_java" -version 2>&1 | sed -n 1p))"
echo "new:     ${new_cmd[*]} ($new_java)"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
bw=(); bc=(); nw=(); nc=()
printf '%-4s %9s %9s %9s %9s\n' run "base wall" "base cpu" "new wall" "new cpu"
for ((i = 1; i <= runs; i++)); do
  if ((i % 2)); then
    read -r w c <<<"$(timed "$log" "${base_cmd[@]}")"; bw+=("$w"); bc+=("$c")
    read -r w c <<<"$(timed "$log" "${new_cmd[@]}")"; nw+=("$w"); nc+=("$c")
  else
    read -r w c <<<"$(timed "$log" "${new_cmd[@]}")"; nw+=("$w"); nc+=("$c")
    read -r w c <<<"$(timed "$log" "${base_cmd[@]}")"; bw+=("$w"); bc+=("$c")
  fi
  printf '%-4s %9s %9s %9s %9s\n' "$i" "${bw[-1]}" "${bc[-1]}" "${nw[-1]}" "${nc[-1]}"
done
mbw="$(median "${bw[@]}")"; mbc="$(median "${bc[@]}")"; mnw="$(median "${nw[@]}")"; mnc="$(median "${nc[@]}")"
printf '%-4s %9s %9s %9s %9s\n' median "$mbw" "$mbc" "$mnw" "$mnc"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the runs"
echo "ratio new / base, CPU time (median of $runs): $(awk -v n="$mnc" -v b="$mbc" 'BEGIN {printf "%.3f", n / b}')"
echo "ratio new / base, wall time (median of $runs): $(awk -v n="$mnw" -v b="$mbw" 'BEGIN {printf "%.3f", n / b}')"
echo "pictures: $(java "$here/tools/ImageCompare.java" "$out/$name-base.png" "$out/$name-new.png" 2>&1)"
