#!/usr/bin/env bash
# Makes the pictures of docs/live-view.md again: for each scene, the live view's `crt preview`
# beside the ray tracer's `crt render` of the same camera, and the Swing panel in its 2x2 layout.
# Needs ImageMagick (montage) for the side-by-side pictures.
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=docs/images/live
mvn -B -q -o test-compile
mvn -B -q -o dependency:build-classpath -Dmdep.outputFile=target/classpath.txt >/dev/null
cp="target/classes:target/test-classes:$(cat target/classpath.txt)"
tmp=$(mktemp -d)
for scene in csg-sculpture dice mirror-room; do
  ./crt preview scenes/$scene.crt -o "$tmp/$scene-live.png" --width 480 --height 270 -q
  ./crt render scenes/$scene.crt -o "$tmp/$scene-traced.png" --width 480 --height 270 -q
  montage "$tmp/$scene-live.png" "$tmp/$scene-traced.png" -tile 2x1 -geometry +4+0 "$out/$scene-live-vs-traced.png"
done
java -cp "$cp" dev.crt.live.LiveViewShots scenes/csg-sculpture.crt "$out/panel-quad.png" quad
java -cp "$cp" dev.crt.live.LiveViewShots scenes/dice.crt "$out/panel-free.png" free
rm -rf "$tmp"
echo "wrote $out/*.png"
