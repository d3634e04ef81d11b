#!/usr/bin/env bash
# Renders the benchmark scene with CRT and with POV-Ray 3.7, alternating, and prints the ratio of
# the medians of the whole-process wall-clock times (CRT / POV-Ray; below 1.0 means CRT is faster).
#
#   bench/povray-compare.sh [--scene NAME] [--runs N] [--warmup N] [--width W --height H] [--out DIR]
#
# Scenes: scenes/box-field.crt and its hand-written twin bench/povray/box-field.pov; with --scene,
# scenes/NAME.crt or bench/scenes/NAME.crt and bench/povray/NAME.pov (e.g. tori: 1,000 tori).
# --scene spheres-written: 10,000 spheres written out literally, each with its own material (CRT)
# and texture (POV-Ray), as exporters write scenes: the same numbers in both files, made on the fly.
# Both use every core (CRT's default; POV-Ray +WT<cores>), one sample per pixel, PNG output.
# POV-Ray is installed from Debian (package povray) when missing and this runs as root.
# Results: a table on stdout (wall-clock and CPU seconds of each run, the render phase alone, CRT
# Mrays/s), and DIR/povray-compare.csv (default DIR: bench/results). GNU time measures each run.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
runs=3
warmup=1
width=1280
height=720
out="$here/results"
scene=box-field

usage() { sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) scene="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --warmup) warmup="$2"; shift 2 ;;
    --width) width="$2"; shift 2 ;;
    --height) height="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "povray-compare: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done

crt_scene="$root/scenes/$scene.crt"
[ -f "$crt_scene" ] || crt_scene="$here/scenes/$scene.crt"
pov_scene="$here/povray/$scene.pov"
if [ "$scene" = spheres-written ]; then
  written="$(mktemp -d)"
  trap 'rm -rf "$written"' EXIT
  crt_scene="$written/spheres-written.crt"
  pov_scene="$written/spheres-written.pov"
  # bench/scenes/spheres.crt and bench/povray/spheres.pov (camera, light, finish) with every sphere
  # and its material written out; a fixed linear congruential generator makes the numbers.
  awk -v n=10000 -v crt="$crt_scene" -v pov="$pov_scene" 'BEGIN {
    print "Settings {" > crt
    print "  camera -> Camera { position -> vec3(0, 0, -32) pointing -> vec3(0, 0, 0) fov -> 40 }" > crt
    print "  lights -> [ PointLight { origin -> vec3(-30, 40, -50) color -> rgb(0.8, 0.8, 0.8) ambient -> 0.2 } ]" > crt
    print "  background -> Background { color -> rgb(0.05, 0.05, 0.08) }" > crt
    print "  recursiondepth -> 0" > crt
    print "}" > crt
    print "Scene {" > crt
    print "#version 3.7;" > pov
    print "global_settings { assumed_gamma 1.0 max_trace_level 1 adc_bailout 0 ambient_light rgb 0.16 }" > pov
    print "camera { perspective location <0, 0, -32> look_at <0, 0, 0> right x * 16 / 9 up y" > pov
    print "  angle 2 * degrees(atan(tan(radians(40 / 2)) * 16 / 9)) }" > pov
    print "light_source { <-30, 40, -50> color rgb 0.8 }" > pov
    print "background { rgb <0.05, 0.05, 0.08> }" > pov
    s = 12345
    r = 16 / sqrt(n)
    for (i = 0; i < n; i++) {
      for (k = 0; k < 6; k++) { s = (s * 1103515245 + 12345) % 2147483648; u[k] = s / 2147483648 }
      x = sprintf("%.6f", 20 * u[0] - 10); y = sprintf("%.6f", 20 * u[1] - 10); z = sprintf("%.6f", 20 * u[2] - 10)
      c1 = sprintf("%.4f", u[3]); c2 = sprintf("%.4f", u[4]); c3 = sprintf("%.4f", u[5])
      printf "  Sphere {\n    center -> vec3(%s, %s, %s)\n    radius -> %.6f\n", x, y, z, r > crt
      printf "    material -> Material {\n      color -> rgb(%s, %s, %s)\n      specular -> 0.4\n    }\n  }\n", c1, c2, c3 > crt
      printf "sphere {\n  <%s, %s, %s>, %.6f\n  texture {\n    pigment { rgb <%s, %s, %s> }\n", x, y, z, r, c1, c2, c3 > pov
      printf "    finish { ambient 1 diffuse 1 phong 0.4 phong_size 30 }\n  }\n}\n" > pov
    }
    print "}" > crt
  }'
fi
if [ ! -f "$crt_scene" ] || [ ! -f "$pov_scene" ]; then
  echo "povray-compare: no scene '$scene': need scenes/$scene.crt or bench/scenes/$scene.crt, and bench/povray/$scene.pov" >&2
  exit 2
fi
cores="$(nproc)"

# --- POV-Ray 3.7 --------------------------------------------------------------------------------
if [ ! -x /usr/bin/time ]; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "povray-compare: installing GNU time (Debian package time)..." >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q time >&2 || { apt-get update -q >&2 && DEBIAN_FRONTEND=noninteractive apt-get install -y -q time >&2; }
  else
    echo "povray-compare: GNU time is needed (/usr/bin/time): sudo apt-get install time" >&2
    exit 3
  fi
fi
if ! command -v povray >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "povray-compare: installing POV-Ray (Debian package povray)..." >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q >&2
    apt-get install -y -q povray >&2
  else
    echo "povray-compare: POV-Ray is not installed; install it with: sudo apt-get install povray" >&2
    exit 3
  fi
fi
pov_version="$(povray --version 2>&1 | grep -m1 '^POV-Ray' || echo 'POV-Ray (unknown version)')"

# --- CRT ----------------------------------------------------------------------------------------
# Build once before timing anything (the launcher builds target/crt.jar when sources changed).
"$root/crt" --version >/dev/null

mkdir -p "$out"
out="$(cd "$out" && pwd)"
if [ "$scene" = box-field ]; then csv="$out/povray-compare.csv"; else csv="$out/povray-compare-$scene.csv"; fi
work="$(mktemp -d)"
trap 'rm -rf "$work" ${written:+"$written"}' EXIT

crt_cmd=("$root/crt" render "$crt_scene" -o "$out/$scene-crt.png" --width "$width" --height "$height" --stats)
# -D no display, -A no antialiasing (NB: +A0 would turn antialiasing ON with threshold 0),
# +WT work threads, +FN PNG, File_Gamma=1.0 to write colours as computed like CRT's gamma 1.
pov_cmd=(povray -D -A "+WT$cores" "+W$width" "+H$height" +FN File_Gamma=1.0 "+I$pov_scene" "+O$out/$scene-povray.png")

# Runs a command; prints its whole-process wall-clock time and its CPU time (user + system, all
# threads), in seconds, separated by a space. The command's own output goes to the log file $1.
timed() {
  local log="$1"; shift
  local tf
  tf="$(mktemp)"
  if ! /usr/bin/time -o "$tf" -f '%e %U %S' "$@" >"$log" 2>&1; then
    echo "povray-compare: command failed: $*" >&2
    tail -20 "$log" >&2
    rm -f "$tf"
    exit 1
  fi
  awk '{printf "%.2f %.2f", $1, $2 + $3}' "$tf"
  rm -f "$tf"
}

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $cores cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)"
echo "java:    $("$root/crt" --version | sed -n 2p) (the one ./crt runs)"
echo "povray:  $pov_version"
if [ "$scene" = box-field ]; then
  echo "scene:   box-field, ${width}x${height}, 1 sample per pixel, recursion depth 5 (POV-Ray max_trace_level 6)"
else
  echo "scene:   $scene (${crt_scene#"$root/"} and ${pov_scene#"$root/"}), ${width}x${height}, 1 sample per pixel"
fi
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) before the runs"
echo "CRT:     ${crt_cmd[*]}"
echo "POV-Ray: (cd $out &&) ${pov_cmd[*]}"
echo

for ((i = 1; i <= warmup; i++)); do
  echo "warm-up $i (not counted)..."
  timed "$work/crt.log" "${crt_cmd[@]}" >/dev/null
  (cd "$out" && timed "$work/pov.log" "${pov_cmd[@]}") >/dev/null
done

crt_times=()
pov_times=()
mrays=()
crt_renders=()
pov_traces=()
crt_cpus=()
pov_cpus=()
echo "run,crt_s,povray_s,crt_mrays_per_s,crt_render_s,povray_trace_s,crt_cpu_s,povray_cpu_s" >"$csv"
echo "wall: whole-process wall-clock seconds; cpu: user + system seconds of all its threads;"
echo "render/trace: the render phase alone, from CRT's --stats and POV-Ray's Trace Time"
printf '%-6s %8s %8s %8s %8s %9s %8s %10s\n' run "CRT" "POV-Ray" "CRT cpu" "POV cpu" "CRT rndr" "POV trc" "CRT Mray/s"
for ((i = 1; i <= runs; i++)); do
  # alternate which one goes first, so that neither always runs right after the other
  if ((i % 2)); then
    read -r c ccpu <<<"$(timed "$work/crt.log" "${crt_cmd[@]}")"
    read -r p pcpu <<<"$(cd "$out" && timed "$work/pov.log" "${pov_cmd[@]}")"
  else
    read -r p pcpu <<<"$(cd "$out" && timed "$work/pov.log" "${pov_cmd[@]}")"
    read -r c ccpu <<<"$(timed "$work/crt.log" "${crt_cmd[@]}")"
  fi
  # the render phase alone: CRT's --stats "render" line, POV-Ray's "Trace Time" (seconds in brackets)
  m="$(awk '/Mrays\/s/ {print $2}' "$work/crt.log" | tail -1)"
  cr="$(awk '$1 == "render" && $3 == "s" {print $2}' "$work/crt.log" | tail -1)"
  pt="$(grep -m1 'Trace Time' "$work/pov.log" | sed 's/.*(\([0-9.]*\) seconds).*/\1/' || true)"
  crt_times+=("$c")
  pov_times+=("$p")
  mrays+=("${m:-0}")
  crt_renders+=("${cr:-0}")
  pov_traces+=("${pt:-0}")
  crt_cpus+=("$ccpu")
  pov_cpus+=("$pcpu")
  printf '%-6s %8s %8s %8s %8s %9s %8s %10s\n' "$i" "$c" "$p" "$ccpu" "$pcpu" "${cr:-?}" "${pt:-?}" "${m:-?}"
  echo "$i,$c,$p,${m:-},${cr:-},${pt:-},$ccpu,$pcpu" >>"$csv"
done

mc="$(median "${crt_times[@]}")"
mp="$(median "${pov_times[@]}")"
mm="$(median "${mrays[@]}")"
mr="$(median "${crt_renders[@]}")"
mt="$(median "${pov_traces[@]}")"
mcc="$(median "${crt_cpus[@]}")"
mpc="$(median "${pov_cpus[@]}")"
ratio="$(awk -v c="$mc" -v p="$mp" 'BEGIN {printf "%.2f", c / p}')"
printf '%-6s %8s %8s %8s %8s %9s %8s %10s\n' median "$mc" "$mp" "$mcc" "$mpc" "$mr" "$mt" "$mm"
echo "median,$mc,$mp,$mm,$mr,$mt,$mcc,$mpc" >>"$csv"
echo
echo "CRT last run --stats:"
sed -n '/^rays/,$p' "$work/crt.log"
echo "POV-Ray last run:"
grep -E 'Trace Time|Parse Time|Rays:|Shadow Ray Tests' "$work/pov.log" | sed 's/^/  /'
echo
echo "ratio CRT / POV-Ray (median of $runs whole-process times): $ratio"
echo "CPU time (CRT / POV-Ray, medians; less sensitive to other load): $(awk -v c="$mcc" -v p="$mpc" 'BEGIN {printf "%.2f", c / p}')"
echo "render phase alone (CRT render / POV-Ray trace, medians): $(awk -v c="$mr" -v p="$mt" 'BEGIN {if (p > 0) printf "%.2f", c / p; else print "?"}')"
if awk -v r="$ratio" 'BEGIN {exit !(r <= 1.0)}'; then
  echo "goal met: CRT takes at most POV-Ray's time"
else
  echo "goal NOT met: CRT takes longer than POV-Ray"
fi
echo "images: $out/$scene-crt.png and $out/$scene-povray.png"
if [ -f "$out/$scene-crt.png" ] && [ -f "$out/$scene-povray.png" ]; then
  echo "difference: $(java "$here/tools/ImageCompare.java" "$out/$scene-crt.png" "$out/$scene-povray.png" 2>&1)"
fi
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min) after the runs"
