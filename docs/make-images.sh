#!/usr/bin/env bash
# Renders the pictures in docs/images that come straight from example scenes, so that they can
# be made again after a change: docs/make-images.sh (from anywhere; uses ./crt).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
images="$root/docs/images"
crt="$root/crt"

# rendering.md, "Scenes from CRT 2015": one 2015-style scene in both shading models.
"$crt" render "$root/scenes/scene-2015.crt" -o "$images/scene-2015-crt.png" -q
"$crt" render "$root/scenes/scene-2015.crt" --shading original -o "$images/scene-2015-original.png" -q
echo "docs/make-images.sh: wrote $images/scene-2015-crt.png and scene-2015-original.png"

# rendering.md, "Spot lights, area lights, Fresnel glass, absorption, 360° cameras": the still
# life, and the same scene as a spherical panorama from the middle of the table.
"$crt" render "$root/scenes/still-life.crt" --supersampling 2 -o "$images/still-life.png" -q
spherical="$(mktemp --suffix=.crt)"
trap 'rm -f "$spherical"' EXIT
sed 's/camera -> Camera { position -> vec3(0, 3.2, -7) pointing -> vec3(0, 0.8, 0) fov -> 42 }/camera -> Camera { position -> vec3(0, 1.6, -1.2) pointing -> vec3(0, 1.6, 3) fov -> 60 projection -> "spherical" }/' \
  "$root/scenes/still-life.crt" > "$spherical"
"$crt" render "$spherical" --width 720 --height 360 -o "$images/still-life-spherical.png" -q
echo "docs/make-images.sh: wrote $images/still-life.png and still-life-spherical.png"

# rendering.md, "Textures, bump maps, glossy finishes, Gooch shading": one small scene per feature
# (docs/scenes), and the materials still life.
for name in solid-textures image-texture bump glossy gooch; do
  "$crt" render "$root/docs/scenes/$name.crt" -o "$images/materials-$name.png" -q
done
"$crt" render "$root/scenes/materials.crt" --supersampling 2 -o "$images/materials.png" -q
echo "docs/make-images.sh: wrote $images/materials-*.png and materials.png"
