#!/usr/bin/env bash
# The error-against-time studies of docs/accuracy.md: crt accuracy on the example scenes and,
# when their folder is given, on the original CRT's demo scenes (data of the original project,
# never committed: pass the folder holding drops.crt, demo01.crt, poster.crt and an assets/ folder
# with images/panorama/*.jpg).
#
#   bench/accuracy.sh [--crt2015 DIR] [--out DIR]
#
# Results: bench/results/accuracy/NAME/{accuracy.csv,rmse.png,ssim.png,...}; the charts are also
# copied to docs/images/accuracy-NAME-{rmse,ssim}.png.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/.." && pwd)"
crt2015=""
out="$here/results/accuracy"
while [ $# -gt 0 ]; do
  case "$1" in
    --crt2015) crt2015="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "accuracy.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out" "$root/docs/images"

study() { # NAME SCRIPT ARGS...
  local name="$1" script="$2"; shift 2
  echo "== $name" >&2
  "$root/crt" accuracy "$script" -o "$out/$name" "$@" | tee "$out/$name.txt"
  cp "$out/$name/rmse.png" "$root/docs/images/accuracy-$name-rmse.png"
  cp "$out/$name/ssim.png" "$root/docs/images/accuracy-$name-ssim.png"
}

# Example scenes: no depth of field, so budgets are n×n grids.
for name in dice csg-sculpture mirror-room spiral; do
  study "$name" "$root/scenes/$name.crt" --budgets 1,4,16,64 --reference-spp 1024
done

if [ -n "$crt2015" ]; then
  # With a lens: 2×2 sub-pixel samples × spp/4 lens samples. drops ships 2×2 × 32 = 128 spp.
  study drops "$crt2015/drops.crt" --assets "$crt2015/assets" --budgets 4,8,16,32,64,128,256 --reference-spp 2048
  study demo01 "$crt2015/demo01.crt" --assets "$crt2015/assets" --budgets 4,8,16,32,64,128 --reference-spp 1024
fi
