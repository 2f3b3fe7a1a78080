#!/bin/sh
# tools/cli/install-stb.sh - make sure stb_image_write.h (Debian's
# libstb-dev) is installed, for `vor raster --png` and the demo's PNG.
# Only host tools use it; the library never does. Quiet when present.
set -eu
[ -f /usr/include/stb/stb_image_write.h ] && exit 0
"$(dirname "$0")/../apt-install.sh" install-stb libstb-dev
