#!/usr/bin/env bash
# Renders the README's screenshot of the viewer: the bundled sphere (whose
# 40 x 20 facets show what each mode makes of a highlight) flat, smooth
# (Gouraud) and Phong side by side, headless, assembled with oiiotool.  `ninja -C build view-screenshot` runs it into
# viewer/view/screenshot.png.
#
#   make_screenshot.sh FIXGL_VIEW MODEL OUT.png
set -euo pipefail
view=$1 model=$2 out=$3
if ! grep -q "GL_WIN_phong_shading yes" <<<"$("$view" --info "$model")"; then
  echo "make_screenshot.sh: this libfixgl has no GL_WIN_phong_shading" >&2
  exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
common=(--headless --size 400x320 --yaw 25 --pitch 30
        --light directional:-30:30 --light point:25:30:2)
labels=(flat Gouraud Phong)
i=0
for shade in flat smooth phong; do
  "$view" "${common[@]}" --shade "$shade" --out "$tmp/$shade.png" "$model" >/dev/null
  # the mode's name in the corner (DejaVu Sans when installed, else none)
  oiiotool "$tmp/$shade.png" \
    --text:x=14:y=30:size=22:color=1,1,1:font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf \
    "${labels[$i]}" -o "$tmp/$shade-label.png" 2>/dev/null \
    || cp "$tmp/$shade.png" "$tmp/$shade-label.png"
  i=$((i + 1))
done
oiiotool "$tmp/flat-label.png" "$tmp/smooth-label.png" "$tmp/phong-label.png" \
  --mosaic:pad=4 3x1 --ch R,G,B -o "$out"
echo "wrote $out"
