#!/usr/bin/env bash
# Opens a rawlog in MRPT's RawLogViewer and/or a .3Dscene in SceneViewer3D on a virtual X display
# (Xvfb), checks that each viewer is still running after loading the file, and saves a screenshot.
#   scripts/check-viewers.sh [--rawlog FILE.rawlog [--entry N]] [--scene FILE.3Dscene] [--out DIR]
#                            [--seconds N]
# --entry N selects the rawlog's entry N in RawLogViewer's tree before the screenshot (its images
# or text shown; needs xdotool). RawLogViewer is started in the rawlog's folder, where MRPT 2.5
# finds the external images (<name>_Images/).
# Exit 0 when every viewer asked for stayed up; 1 when one exited early (its output is printed).
set -euo pipefail
rawlog="" scene="" out="out/viewer-check" secs=8 entry=""
while [ $# -gt 0 ]; do
  case "$1" in
    --rawlog) rawlog=$2; shift 2 ;;
    --scene) scene=$2; shift 2 ;;
    --entry) entry=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --seconds) secs=$2; shift 2 ;;
    -h|--help) sed -n 2,9p "$0"; exit 0 ;;
    *) echo "check-viewers: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done
[ -n "$rawlog$scene" ] || { echo "check-viewers: give --rawlog and/or --scene" >&2; exit 2; }
for f in $rawlog $scene; do [ -f "$f" ] || { echo "check-viewers: no such file: $f" >&2; exit 2; }; done
[ -z "$entry" ] || [[ "$entry" =~ ^[0-9]+$ ]] || { echo "check-viewers: --entry takes an entry number, not '$entry'" >&2; exit 2; }
tools="Xvfb xwd"; [ -z "$entry" ] || tools="$tools xdotool"
for tool in $tools; do
  command -v $tool >/dev/null || { echo "check-viewers: $tool missing: run scripts/install-deps.sh" >&2; exit 1; }
done
mkdir -p "$out"
display=":$((90 + RANDOM % 100))"
Xvfb "$display" -screen 0 1400x1000x24 >/dev/null 2>&1 &
xvfb_pid=$!
trap 'kill $xvfb_pid 2>/dev/null || true' EXIT
sleep 1

# RawLogViewer's main window full-screen, its tip closed, entry $entry of its tree selected
select_entry() {
  export DISPLAY=$display
  for w in $(xdotool search --name "Tip of the Day" 2>/dev/null); do xdotool windowclose "$w" 2>/dev/null || true; done
  local main
  main=$(xdotool search --name "RawlogViewer - Part" | head -1)
  [ -n "$main" ] || { echo "check-viewers: RawLogViewer's window not found" >&2; return 1; }
  xdotool windowmove "$main" 0 0 windowsize "$main" 1400 1000
  sleep 1
  xdotool mousemove 100 122 click 1  # entry 0, under the tree's root at this size
  for _ in $(seq 1 "$entry"); do xdotool key Down; done
  sleep 2
}

check() {  # name, program, file
  local name=$1 prog=$2 file=$3 log
  log="$(realpath "$out")/$name.log"
  (cd "$(dirname "$file")" && DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1 exec "$prog" "$(basename "$file")") >"$log" 2>&1 &
  local pid=$!
  sleep "$secs"
  if ! kill -0 $pid 2>/dev/null; then
    echo "check-viewers: $prog exited while loading $file:" >&2
    cat "$log" >&2
    return 1
  fi
  if [ "$prog" = RawLogViewer ] && [ -n "$entry" ]; then select_entry || return 1; fi
  DISPLAY=$display xwd -root -silent > "$out/$name.xwd"
  if [ -x /usr/bin/convert ]; then
    /usr/bin/convert "$out/$name.xwd" "$out/$name.png" && rm -f "$out/$name.xwd"
  fi
  kill $pid 2>/dev/null || true
  wait $pid 2>/dev/null || true
  echo "check-viewers: $prog stayed up with $file; screenshot in $out/$name.png"
}

status=0
[ -n "$rawlog" ] && { check rawlogviewer RawLogViewer "$rawlog" || status=1; }
[ -n "$scene" ] && { check sceneviewer SceneViewer3D "$scene" || status=1; }
exit $status
