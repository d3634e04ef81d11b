#!/usr/bin/env bash
# Makes the screenshots of docs/studio.md again: starts the studio on a virtual X display
# with fresh settings, drives it with real key presses and photographs the screen.
# Needs: Xvfb, xdotool and ImageMagick's import (Debian: xvfb xdotool imagemagick).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$here/docs/images/studio"
mkdir -p "$out"
for tool in Xvfb xdotool import; do
  command -v "$tool" >/dev/null 2>&1 || { echo "studio-screenshots: $tool is needed" >&2; exit 3; }
done

# SCREENSHOT_DISPLAY=N uses display :N (it must be free); else the first free one from :150.
display="${SCREENSHOT_DISPLAY:-}"
[ -n "$display" ] || for n in $(seq 150 199); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=$n; break; fi
done
[ -n "$display" ] || { echo "studio-screenshots: no free X display" >&2; exit 1; }
work="$(mktemp -d)"
Xvfb ":$display" -screen 0 1280x800x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
studio=""
cleanup() {
  [ -n "$studio" ] && kill "$studio" 2>/dev/null || true
  kill "$xvfb" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
export DISPLAY=":$display"
sleep 1
shot() { sleep "$2"; import -window root "$out/$1.png"; echo "wrote docs/images/studio/$1.png"; }

# The Animation, System and settings panels, in a studio of their own on a copy of orbit.crt (light theme).
cp "$here/scenes/orbit.crt" "$work/orbit.crt"
XDG_CONFIG_HOME="$work/anim-config" XDG_STATE_HOME="$work/anim-state" \
  CRT_JAVA_OPTS="-Xss16m -Djava.util.prefs.userRoot=$work/anim-prefs" "$here/crt" studio "$work/orbit.crt" &
studio=$!
sleep "${STUDIO_START_WAIT:-12}"
# A click into the editor gives the window the focus (there is no window manager).
xdotool mousemove 400 400 click 1
xdotool key alt+8
sleep 1
xdotool key alt+7
shot animation-preview 3
# Shift+F5 renders the frames 0..47 in the Animation panel.
xdotool key shift+F5
shot animation "${FRAMES_WAIT:-40}"
shot system 2
xdotool key ctrl+alt+s
shot settings-dialog 3
xdotool key Escape
kill "$studio" 2>/dev/null || true
wait "$studio" 2>/dev/null || true
studio=""

# The script is a copy, so that the edits below never touch the example.
cp "$here/scenes/dice.crt" "$work/dice.crt"
XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" \
  CRT_JAVA_OPTS="-Xss16m -Djava.util.prefs.userRoot=$work/prefs" "$here/crt" studio "$work/dice.crt" &
studio=$!
sleep "${STUDIO_START_WAIT:-12}"
xdotool mousemove 400 400

xdotool key F5
shot light-render "${RENDER_WAIT:-15}"

# The live view (OpenGL, offscreen through EGL) in the place of the Render panel, then back.
xdotool key alt+4
shot light-live "${LIVE_WAIT:-8}"
xdotool key alt+2
sleep 1

xdotool key ctrl+End
xdotool type --delay 40 $'\nbig = Sphere { radius -> size }'
sleep 2
# Hover the squiggled word for its tooltip (where the fresh default layout puts line 34).
xdotool mousemove 240 572
shot light-error 2
xdotool mousemove 400 300

xdotool key ctrl+shift+t
shot dark-error 3

xdotool type --delay 40 $'\nScene { Box { c'
xdotool key ctrl+space
shot dark-completion 2
xdotool key Escape

# The scene as objects (Navigator, Properties, Insert): a second studio on a scene with CSG, a
# macro and a shared material, fresh settings so that the default layout is the one photographed.
kill "$studio" 2>/dev/null || true
wait "$studio" 2>/dev/null || true
sed 's/width -> 160 height -> 120/width -> 480 height -> 360/' "$here/src/test/resources/dev/crt/studio/objects.crt" > "$work/objects.crt"
XDG_CONFIG_HOME="$work/config2" XDG_STATE_HOME="$work/state2" \
  CRT_JAVA_OPTS="-Xss16m -Djava.util.prefs.userRoot=$work/prefs2" "$here/crt" studio "$work/objects.crt" &
studio=$!
sleep "${STUDIO_START_WAIT:-12}"
# A click below the script's last line gives the editor the focus (there is no window manager).
xdotool mousemove 500 540 click 1
xdotool key F5
sleep "${RENDER_WAIT:-15}"
# Expand the CSG node and select the ball (rows of the fresh default layout's tree).
xdotool mousemove 33 251 click 1
sleep 1
xdotool mousemove 104 232 click 1
shot objects-navigator 3
# The colour's "…" button opens the colour chooser with the 0–1 values.
xdotool mousemove 200 446 click 1
shot objects-color 3
xdotool key Escape
sleep 1
xdotool mousemove 113 93 click 1
xdotool type --delay 60 "sph"
shot objects-filter 2
xdotool key ctrl+a BackSpace
xdotool mousemove 222 10 click 1
shot objects-insert 2
xdotool key Escape
