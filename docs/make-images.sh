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
