#!/usr/bin/env bash
# Render the POV-Ray scenes written by `cic render --out DIR` and join them into DIR/out.mp4.
#   scripts/render-video.sh DIR [--width W] [--height H] [--fps F] [--jobs N]
# Needs povray and ffmpeg (scripts/install-deps.sh installs both).
set -euo pipefail

usage() { sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }

[[ $# -ge 1 ]] || usage
case $1 in -h|--help) sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
dir=$1; shift
width=640 height=480 fps=25 jobs=$(nproc 2>/dev/null || echo 1)
while [[ $# -gt 0 ]]; do
  case $1 in
    --width) width=${2:?}; shift 2 ;;
    --height) height=${2:?}; shift 2 ;;
    --fps) fps=${2:?}; shift 2 ;;
    --jobs) jobs=${2:?}; shift 2 ;;
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

ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -i "$dir/frame_%05d.png" \
  -c:v libx264 -pix_fmt yuv420p -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" "$dir/out.mp4"
echo "$dir/out.mp4"
