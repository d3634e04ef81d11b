#!/usr/bin/env bash
# What each switchable feature of the renderer costs a scene that does not use it (issue 14, part 5):
# ns per ray with every feature present against each one switched off (-Dcrt.without=NAME) and all
# of them off, all settings in one JVM (bench/FeatureCost.java: one class loader per setting over the
# same jar, rounds alternating, one render thread, its CPU time), then the JIT's evidence that a
# switch off removes its tests (bench/tools/JitBranches.java over two compilation logs).
#
#   bench/feature-cost.sh [--rounds N] [--size WxH] [--jit-size WxH] [--jar JAR] [--java JAVA] [--no-jit]
#                         [SCENE.crt [ASSETS_DIR]]
#
# Defaults: scenes/box-field.crt at 320x180, 60 rounds, the JIT's logs at 480x270, target/crt.jar
# (built when missing), the java on the PATH. The 2015 drops scene (depth of field, 128 samples a
# pixel): bench/feature-cost.sh --size 80x60 --rounds 30 --jit-size 80x60 DATA/drops.crt DATA/assets.
# Results: bench/results/feature-cost-SCENE.csv and .txt.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
rounds=60
size=320x180
jit_size=480x270
jar="$root/target/crt.jar"
java=java
jit=1
usage() { sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --rounds) rounds="$2"; shift 2 ;;
    --size) size="$2"; shift 2 ;;
    --jit-size) jit_size="$2"; shift 2 ;;
    --jar) jar="$2"; shift 2 ;;
    --java) java="$2"; shift 2 ;;
    --no-jit) jit=0; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "feature-cost: unknown option '$1'" >&2; usage >&2; exit 2 ;;
    *) break ;;
  esac
done
scene="${1:-$root/scenes/box-field.crt}"
assets="${2:-}"
[ -f "$scene" ] || { echo "feature-cost: no such scene: $scene" >&2; exit 2; }
[ -z "$assets" ] || [ -d "$assets" ] || { echo "feature-cost: no such assets folder: $assets" >&2; exit 2; }
[[ "$size" =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "feature-cost: --size wants WxH, got '$size'" >&2; exit 2; }
width="${BASH_REMATCH[1]}"
height="${BASH_REMATCH[2]}"
[[ "$jit_size" =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "feature-cost: --jit-size wants WxH, got '$jit_size'" >&2; exit 2; }
jit_width="${BASH_REMATCH[1]}"
jit_height="${BASH_REMATCH[2]}"
if [ ! -f "$jar" ]; then
  [ "$jar" = "$root/target/crt.jar" ] || { echo "feature-cost: no such jar: $jar" >&2; exit 2; }
  (cd "$root" && mvn -B -q -o package -DskipTests)
fi
props=()
[ -z "$assets" ] || props=("-Dcrt.assets=$(cd "$assets" && pwd)")
name="$(basename "$scene" .crt)"
mkdir -p "$here/results"
"$java" -version 2>&1 | head -1 | tee "$here/results/feature-cost-$name.txt"
"$java" "${props[@]}" "$here/FeatureCost.java" "$jar" "$scene" "$width" "$height" "$rounds" \
  "$here/results/feature-cost-$name.csv" | tee -a "$here/results/feature-cost-$name.txt"

if [ "$jit" = 1 ]; then
  # The same render twice, every feature present and all off, with the JIT's compilation log.
  logs="$(mktemp -d)"
  trap 'rm -rf "$logs"' EXIT
  for without in "" all; do
    "$java" "${props[@]}" -XX:+UnlockDiagnosticVMOptions -XX:+LogCompilation -XX:LogFile="$logs/jit-${without:-none}.log" \
      -Dcrt.without="$without" -jar "$jar" render "$scene" --width "$jit_width" --height "$jit_height" --threads 1 -q -o "$logs/${without:-none}.png" \
      ${assets:+--assets "$assets"} >/dev/null
  done
  cmp -s "$logs/none.png" "$logs/all.png" || { echo "feature-cost: the two renders differ" >&2; exit 1; }
  echo "JIT: A = every feature present, B = -Dcrt.without=all (the same picture, ${jit_size}, one thread)" \
    | tee -a "$here/results/feature-cost-$name.txt"
  "$java" "$here/tools/JitBranches.java" "$logs/jit-none.log" "$logs/jit-all.log" | tee -a "$here/results/feature-cost-$name.txt"
fi
