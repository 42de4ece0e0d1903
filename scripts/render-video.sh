#!/usr/bin/env bash
# Render the POV-Ray scenes written by `cic render --out DIR` and join them into DIR/out.mp4.
#   scripts/render-video.sh DIR [--width W] [--height H] [--fps F] [--jobs N] [--overlay]
# --overlay writes the scenes' title (who is shown) and the time on the video.
# Needs povray and ffmpeg (scripts/install-deps.sh installs both).
set -euo pipefail

usage() { sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

[[ $# -ge 1 ]] || usage
case $1 in -h|--help) sed -n '2,5p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
dir=$1; shift
width=640 height=480 fps=25 jobs=$(nproc 2>/dev/null || echo 1) overlay=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?}; shift 2 ;;
    --height) height=${2:?}; shift 2 ;;
    --fps) fps=${2:?}; shift 2 ;;
    --jobs) jobs=${2:?}; shift 2 ;;
    --overlay) overlay=1; shift ;;
    -h|--help) usage ;;
    *) echo "render-video.sh: unknown option '$1'" >&2; usage ;;
  esac
done
for n in "$width" "$height" "$fps" "$jobs"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "render-video.sh: '$n' is not a positive integer" >&2; exit 2; }
done
[[ -d $dir ]] || { echo "render-video.sh: no such folder: $dir" >&2; exit 2; }
for tool in povray ffmpeg; do
  command -v "$tool" >/dev/null || { echo "render-video.sh: $tool not found (run scripts/install-deps.sh)" >&2; exit 2; }
done
shopt -s nullglob
scenes=("$dir"/frame_*.pov)
[[ ${#scenes[@]} -gt 0 ]] || { echo "render-video.sh: no frame_*.pov in $dir (write them with cic render --out $dir)" >&2; exit 2; }

echo "render-video.sh: rendering ${#scenes[@]} frames at ${width}x${height} with $jobs jobs" >&2
# One povray per frame; -D: no display window; +A: anti-aliasing. Runs inside DIR so the includes resolve.
export width height
printf '%s\n' "${scenes[@]##*/}" | (cd "$dir" && xargs -P "$jobs" -I{} sh -c \
  'povray +I"$1" +O"${1%.pov}.png" +FN +W"$width" +H"$height" +A0.3 -D -V -GA 2>"${1%.pov}.log" || { cat "${1%.pov}.log" >&2; exit 255; }; rm -f "${1%.pov}.log"; printf . >&2' _ {})
echo >&2   # a dot per frame rendered, above: the progress

filter="pad=ceil(iw/2)*2:ceil(ih/2)*2"
if [[ $overlay = 1 ]]; then
  # The title cic render wrote into the first scene ("// cic frame 1 of N, t = T s, TITLE"),
  # and each frame's scene time, from the first two scenes' t (whatever --fps plays them at).
  head=$(head -n 1 "$dir/frame_00000.pov")
  title=$(printf '%s' "$head" | sed -n 's/^\/\/ cic frame [0-9]* of [0-9]*, t = [0-9.]* s, //p')
  scene_t() { head -n 1 "$1" 2>/dev/null | sed -n 's/^\/\/ cic frame [0-9]* of [0-9]*, t = \([0-9.]*\) s.*/\1/p'; }
  t0=$(scene_t "$dir/frame_00000.pov"); t1=$(scene_t "$dir/frame_00001.pov")
  dt=$(awk -v a="${t0:-0}" -v b="${t1:-0}" 'BEGIN { d = b - a; print (d > 0 ? d : 0) }')
  title=${title//[\':%]/ }   # characters drawtext would read as syntax
  size=$(( height / 24 > 10 ? height / 24 : 10 ))
  at="(${t0:-0}+n*${dt})"
  filter+=",drawtext=text='${title}':x=10:y=10:fontsize=${size}:fontcolor=black:box=1:boxcolor=white@0.7"
  filter+=",drawtext=text='t = %{eif\\:${at}\\:d}.%{eif\\:mod(${at}*10\\,10)\\:d} s':x=10:y=$((10 + size + 6)):fontsize=${size}:fontcolor=black:box=1:boxcolor=white@0.7"
fi
ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -i "$dir/frame_%05d.png" \
  -c:v libx264 -pix_fmt yuv420p -vf "$filter" "$dir/out.mp4"
echo "$dir/out.mp4"
