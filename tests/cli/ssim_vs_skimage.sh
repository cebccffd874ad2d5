#!/bin/sh
# ssim_vs_skimage.sh CASES_BINARY SCRIPT SCRATCH: penumbra's SSIM against scikit-image's.
set -u
rm -rf "$3" && mkdir -p "$3" || exit 1
"$1" "$3" || { echo "writing the SSIM cases failed"; exit 1; }
exec /usr/bin/python3 "$2" "$3"
